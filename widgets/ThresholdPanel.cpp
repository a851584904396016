#include "widgets/ThresholdPanel.h"

#include "core/ColourClasses.h"
#include "widgets/ConfigDocument.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTextDocument>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace omnitune {

namespace {

// Space around the search box (px): it keeps clear of the dock's edges.
constexpr int kSearchMarginPx = 3;

struct Section {
    const char* key;
    const char* title;
};

const Section kSections[] = {
    {"denoise", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Denoise (noisy frames)")},
    {"edges", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Edges (Canny)")},
    {"hough", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Specific Hough (thesis 4.1)")},
    {"opencv_hough", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "OpenCV Hough (thesis 4.2)")},
    {"validation", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Validation (thesis 4.4)")},
    {"sensors", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Radial sensors (thesis fig. 4.3)")},
    {"algorithm", QT_TRANSLATE_NOOP("omnitune::ThresholdPanel", "Algorithm")},
};

const QString kBallHintKey = QStringLiteral("validation.ball_hint_class");

QString qs(const std::string& s) { return QString::fromStdString(s); }

bool inSection(const ConfigKey& k, const char* section)
{
    const std::string prefix = std::string(section) + ".";
    return k.path.compare(0, prefix.size(), prefix) == 0;
}

// "validation.min_non_green_pct" (unit %) -> "Min non-green (%)" as rich text; the full path is
// in the tooltip.
QString rowLabel(const ConfigKey& k)
{
    // Named after what it limits: "Min radius" is already the OpenCV circles' row.
    if (k.path == "validation.min_radius_px") return ThresholdPanel::tr("Min expected radius (px)");
    QStringList words = qs(k.path.substr(k.path.find('.') + 1)).split(QLatin1Char('_'));
    if (words.size() > 1 && ((k.unit == "%" && words.last() == QLatin1String("pct")) ||
                             (k.unit == "px" && words.last() == QLatin1String("px"))))
        words.removeLast();
    QString text = words.join(QLatin1Char(' '));
    text.replace(QLatin1String("non green"), QLatin1String("non-green"))
        .replace(QLatin1String("non black"), QLatin1String("non-black"))
        .replace(QLatin1String("acc "), QLatin1String("accumulator "));
    if (text != QLatin1String("dp")) text[0] = text[0].toUpper();
    text = text.toHtmlEscaped();
    // The unit wraps as a whole: "(fraction)" or "(votes)" split inside reads as nonsense. Qt's rich
    // text has no inline nowrap, so word joiners (U+2060) forbid the breaks.
    if (!k.unit.empty()) {
        QString unit = QStringLiteral("(%1)").arg(qs(k.unit));
        for (int i = unit.size() - 1; i > 0; --i) unit.insert(i, QChar(0x2060));
        text += QLatin1Char(' ') + unit.toHtmlEscaped();
    }
    return text;
}

QString formatNumber(double v) { return QString::number(v, 'g', 10); }

QString formatList(const std::vector<double>& values)
{
    QStringList parts;
    for (double v : values) parts << formatNumber(v);
    return parts.join(QStringLiteral(", "));
}

// "70, 105 140;170" -> {70, 105, 140, 170}; numbers in the C locale (the comma separates).
std::optional<std::vector<double>> parseList(const QString& text, QString* error)
{
    static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
    const QStringList parts = text.split(separators, Qt::SkipEmptyParts);
    if (parts.isEmpty()) {
        *error = ThresholdPanel::tr("enter at least one number, e.g. 70, 105, 140");
        return std::nullopt;
    }
    std::vector<double> values;
    for (const QString& p : parts) {
        bool ok = false;
        const double v = QLocale::c().toDouble(p, &ok);
        if (!ok || !std::isfinite(v)) {
            *error = ThresholdPanel::tr("\"%1\" is not a number (separate numbers with commas, decimals with a point)").arg(p);
            return std::nullopt;
        }
        values.push_back(v);
    }
    return values;
}

double span(const ConfigKey& k) { return k.max - k.min; }

// Percentages with one decimal; otherwise finer for narrow ranges, and never so coarse that
// the default cannot be shown exactly.
int decimalsFor(const ConfigKey& k)
{
    int d = k.unit == "%" ? 1 : span(k) <= 1 ? 3 : span(k) <= 10 ? 2 : 1;
    const double def = std::get<double>(k.get(Config{}));
    while (d < 6) {
        const double scaled = def * std::pow(10.0, d);
        if (std::abs(scaled - std::round(scaled)) < 1e-6) break;
        ++d;
    }
    return d;
}

double stepFor(const ConfigKey& k)
{
    if (k.unit == "%") return 1.0;
    if (span(k) <= 1) return 0.01;
    if (span(k) <= 10) return 0.1;
    if (span(k) <= 100) return 0.5;
    return 1.0;
}

QString tooltipFor(const ConfigKey& k)
{
    const QString unit = k.unit.empty() ? QString() : QStringLiteral(" ") + qs(k.unit);
    QString range;
    switch (k.type) {
    case ValueType::Int:
    case ValueType::Double: range = formatNumber(k.min) + QStringLiteral(" .. ") + formatNumber(k.max) + unit; break;
    case ValueType::DoubleList:
        range = ThresholdPanel::tr("each %1 .. %2%3, separated by commas").arg(formatNumber(k.min), formatNumber(k.max), unit);
        break;
    case ValueType::Choice: {
        QStringList choices;
        for (const std::string& c : k.choices) choices << qs(c);
        range = choices.join(QStringLiteral(", "));
        break;
    }
    case ValueType::Bool: range = ThresholdPanel::tr("on / off"); break;
    case ValueType::Text: break;
    }
    const ConfigValue def = k.get(Config{});
    QString defText = qs(formatConfigValue(def));
    if (k.type == ValueType::DoubleList) defText = formatList(std::get<std::vector<double>>(def));
    if (k.type == ValueType::Bool) defText = std::get<bool>(def) ? ThresholdPanel::tr("on") : ThresholdPanel::tr("off");
    if (k.fromThesis) defText += ThresholdPanel::tr(" (thesis)");
    QString html = QStringLiteral("<p><b>%1</b></p><p>%2</p>").arg(qs(k.path).toHtmlEscaped(), qs(k.meaning).toHtmlEscaped());
    const QString rangeWord = k.type == ValueType::Choice ? ThresholdPanel::tr("Choices") : ThresholdPanel::tr("Range");
    if (!range.isEmpty())
        html += ThresholdPanel::tr("<p>%1: %2<br/>Default: %3</p>").arg(rangeWord, range.toHtmlEscaped(), (defText + unit).toHtmlEscaped());
    else
        html += ThresholdPanel::tr("<p>Default: %1</p>").arg((defText + unit).toHtmlEscaped());
    return html;
}

QString withoutAnonymousFile(QString message)
{
    // ConfigIssue::toString names the file; an in-memory config is "<config>".
    const QString prefix = QStringLiteral("<config>: ");
    if (message.startsWith(prefix)) message.remove(0, prefix.size());
    return message;
}

}  // namespace

ThresholdPanel::ThresholdPanel(ConfigDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc)
{
    Q_ASSERT(doc_);
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);
    for (const Section& section : kSections) {
        const QString title = tr(section.title);
        auto* group = new QGroupBox(title, content);
        auto* form = new QFormLayout(group);
        form->setContentsMargins(6, 6, 6, 6);
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);  // the area bounds get a line of their own
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        form->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter);
        for (const ConfigKey& k : configSchema())
            if (inSection(k, section.key)) addEditor(k, form, group, title);
        column->addWidget(group);
    }
    noMatch_ = new QLabel(content);
    noMatch_->setObjectName(QStringLiteral("noMatch"));
    noMatch_->setWordWrap(true);
    noMatch_->hide();
    column->addWidget(noMatch_);
    column->addStretch(1);
    // One label column for all groups, so that the editors line up; long names wrap.
    int labelWidth = 0;
    for (QLabel* label : labels_) labelWidth = std::max(labelWidth, label->sizeHint().width());
    labelWidth = std::min(labelWidth, fontMetrics().averageCharWidth() * 18);
    for (QLabel* label : labels_) {
        label->setWordWrap(true);
        label->setFixedWidth(labelWidth);
    }

    auto* scroll = new QScrollArea(this);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(content->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("status"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QPalette pal = status_->palette();
    pal.setColor(QPalette::WindowText, QColor(0xb0, 0x00, 0x00));
    status_->setPalette(pal);
    status_->hide();

    search_ = new QLineEdit(this);
    search_->setObjectName(QStringLiteral("search"));
    search_->setPlaceholderText(tr("Find a threshold (e.g. circ, canny, valid)"));
    search_->setClearButtonEnabled(true);
    search_->setToolTip(tr("Shows only the thresholds whose name, key or group contains what you type. "
                           "Escape clears it."));
    search_->installEventFilter(this);  // Escape clears
    connect(search_, &QLineEdit::textChanged, this, [this, scroll](const QString& text) {
        setFilter(text);
        scroll->verticalScrollBar()->setValue(0);  // the first match, not the old scroll position
    });

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // Clear of the dock's edges, which the window's own edge is on the right (it ran under it),
    // and ending where the groups under it end, not over their scroll bar.
    auto* searchRow = new QHBoxLayout;
    searchRow->setContentsMargins(kSearchMarginPx, kSearchMarginPx,
                                  scroll->verticalScrollBar()->sizeHint().width() + kSearchMarginPx, 0);
    searchRow->addWidget(search_);
    layout->addLayout(searchRow);
    layout->addWidget(scroll, 1);
    layout->addWidget(status_);

    connect(doc_, &ConfigDocument::changed, this, &ThresholdPanel::onDocumentChanged);
    onDocumentChanged(QString());
}

ThresholdPanel::~ThresholdPanel()
{
    // A focused editor finishes its edit while ~QWidget deletes it, after this class's members
    // are gone: it must not reach them.
    for (QObject* child : findChildren<QObject*>()) child->disconnect(this);
}

QStringList ThresholdPanel::sections()
{
    QStringList out;
    for (const Section& s : kSections) out << QLatin1String(s.key);
    return out;
}

QWidget* ThresholdPanel::editorFor(const QString& key) const { return editors_.value(key, nullptr); }

QString ThresholdPanel::statusMessage() const { return status_->text(); }

void ThresholdPanel::setFilter(const QString& text)
{
    const QStringList words = text.toLower().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QHash<QGroupBox*, bool> groupShown;
    bool any = false;
    for (const Row& row : rows_) {
        const bool shown = std::all_of(words.begin(), words.end(), [&row](const QString& w) { return row.text.contains(w); });
        row.label->setVisible(shown);
        row.editor->setVisible(shown);
        groupShown[row.group] |= shown;
        any |= shown;
    }
    for (auto it = groupShown.cbegin(); it != groupShown.cend(); ++it) it.key()->setVisible(it.value());
    noMatch_->setText(tr("No threshold matches \"%1\".").arg(text.trimmed()));
    noMatch_->setVisible(!any);
}

void ThresholdPanel::addEditor(const ConfigKey& k, QFormLayout* form, QGroupBox* group, const QString& groupTitle)
{
    const QString key = qs(k.path);
    QWidget* editor = nullptr;
    // Text typed into a spin box or line edit, not yet committed, must survive document changes.
    auto trackTyping = [this, key](QLineEdit* line) {
        if (line) connect(line, &QLineEdit::textEdited, this, [this, key] { typing_.insert(key); });
    };
    // A spin box: typing starts the guard, finishing the edit ends it and shows the document.
    auto watchSpinTyping = [this, key, trackTyping](QAbstractSpinBox* spin) {
        connect(spin, &QAbstractSpinBox::editingFinished, this, [this, key] {
            typing_.remove(key);
            syncEditor(key);
        });
        trackTyping(spin->findChild<QLineEdit*>());
    };
    switch (k.type) {
    case ValueType::Int: {
        auto* spin = new QSpinBox;
        spin->setRange(int(k.min), int(k.max));
        spin->setKeyboardTracking(false);
        spin->setAccelerated(true);
        connect(spin, qOverload<int>(&QSpinBox::valueChanged), this, [this, key](int v) { apply(key, v); });
        watchSpinTyping(spin);
        editor = spin;
        break;
    }
    case ValueType::Double: {
        auto* spin = new QDoubleSpinBox;
        spin->setDecimals(decimalsFor(k));
        spin->setRange(k.min, k.max);
        spin->setSingleStep(stepFor(k));
        spin->setKeyboardTracking(false);
        spin->setAccelerated(true);
        connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, key, spin](double v) {
            // The editor shows the document's value rounded to its decimals: committing that
            // unchanged text must not round the config.
            const double current = std::get<double>(doc_->value(key));
            if (QString::number(current, 'f', spin->decimals()) == QString::number(v, 'f', spin->decimals())) return;
            apply(key, v);
        });
        watchSpinTyping(spin);
        editor = spin;
        break;
    }
    case ValueType::Bool: {
        auto* check = new QCheckBox;
        connect(check, &QCheckBox::toggled, this, [this, key](bool on) { apply(key, on); });
        editor = check;
        break;
    }
    case ValueType::Choice: {
        auto* combo = new QComboBox;
        for (const std::string& c : k.choices) combo->addItem(qs(c), qs(c));
        connect(combo, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, key, combo](int index) {
            if (index >= 0) apply(key, combo->itemData(index).toString().toStdString());
        });
        editor = combo;
        break;
    }
    case ValueType::DoubleList:
    case ValueType::Text: {
        if (key == kBallHintKey) {
            // A class name: picked from the classes that may be the ball (syncEditor fills it).
            auto* combo = new QComboBox;
            combo->setProperty("colourClassNames", true);
            connect(combo, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, key, combo](int index) {
                if (index >= 0) apply(key, combo->itemData(index).toString().toStdString());
            });
            editor = combo;
            break;
        }
        auto* line = new QLineEdit;
        if (k.type == ValueType::DoubleList) {
            const QString example = formatList(std::get<std::vector<double>>(k.get(Config{})));
            line->setPlaceholderText(tr("e.g. %1").arg(example));
            // Wide enough for the thesis' six bounds; the form gives it a line of its own.
            line->setMinimumWidth(line->fontMetrics().horizontalAdvance(example + QStringLiteral(", 275")) + 12);
            connect(line, &QLineEdit::editingFinished, this, [this, key] {
                typing_.remove(key);
                applyListText(key);
            });
        } else {
            connect(line, &QLineEdit::editingFinished, this, [this, key, line] {
                typing_.remove(key);
                if (apply(key, line->text().toStdString())) syncEditor(key);
            });
        }
        trackTyping(line);
        editor = line;
        break;
    }
    }
    editor->setObjectName(key);
    editor->setToolTip(tooltipFor(k));
    editor->installEventFilter(this);  // undo keys (all editors), wheel (spin and combo boxes)
    if (qobject_cast<QAbstractSpinBox*>(editor) || qobject_cast<QComboBox*>(editor))
        editor->setFocusPolicy(Qt::StrongFocus);
    auto* label = new QLabel(rowLabel(k));
    label->setTextFormat(Qt::RichText);
    label->setToolTip(editor->toolTip());
    label->setBuddy(editor);
    labels_ << label;
    QTextDocument plain;
    plain.setHtml(label->text());
    const QString haystack = key + QLatin1Char(' ') + plain.toPlainText().remove(QChar(0x2060)) + QLatin1Char(' ') + groupTitle;
    rows_.push_back({label, editor, group, haystack.toLower()});
    form->addRow(label, editor);
    editors_.insert(key, editor);
}

bool ThresholdPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == search_ && event->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape &&
        !search_->text().isEmpty()) {
        search_->clear();
        return true;
    }
    if (watched == search_ && event->type() == QEvent::ShortcutOverride &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape && !search_->text().isEmpty()) {
        // The window's Escape (keyboard back to the panes) waits until the search is cleared.
        event->accept();
        return true;
    }
    if (event->type() == QEvent::ShortcutOverride) {
        // Ctrl+Z / Ctrl+Shift+Z undo and redo the config, also with the cursor still in the
        // field just edited: a value applies on Return, so the field's own text undo would
        // only swallow the key (newcomers pressed it twice and saw nothing happen).
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) return true;
    }
    if (event->type() == QEvent::Wheel && (qobject_cast<QAbstractSpinBox*>(watched) || qobject_cast<QComboBox*>(watched))) {
        auto* w = qobject_cast<QWidget*>(watched);
        if (w && !w->hasFocus()) {
            event->ignore();  // goes on to the scroll area
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

bool ThresholdPanel::apply(const QString& key, const ConfigValue& value)
{
    if (const auto refused = doc_->setValue(key, value)) {
        QWidget* editor = editors_.value(key);
        if (qobject_cast<QLineEdit*>(editor)) {
            setInvalid(editor, true);  // keep the text so that it can be corrected
        } else {
            typing_.remove(key);
            syncEditor(key);
        }
        refuse(withoutAnonymousFile(*refused));
        return false;
    }
    setInvalid(editors_.value(key), false);
    setStatus(QString());
    return true;
}

void ThresholdPanel::applyListText(const QString& key)
{
    auto* line = qobject_cast<QLineEdit*>(editors_.value(key));
    Q_ASSERT(line);
    QString error;
    const auto values = parseList(line->text(), &error);
    if (!values) {
        setInvalid(line, true);
        refuse(QStringLiteral("%1: %2").arg(key, error));
        return;
    }
    if (apply(key, *values)) syncEditor(key);  // canonical text even when nothing changed
}

void ThresholdPanel::refuse(const QString& message)
{
    setStatus(message);
    emit editRefused(message);
}

void ThresholdPanel::onDocumentChanged(const QString& key)
{
    if (key.isEmpty()) {
        for (auto it = editors_.cbegin(); it != editors_.cend(); ++it) syncEditor(it.key());
    } else if (editors_.contains(key)) {
        syncEditor(key);
    }
    // The ball hint's choices are the class names: any change may have renamed or removed one.
    if (!key.isEmpty() && key != kBallHintKey && editors_.contains(kBallHintKey)) syncEditor(kBallHintKey);
}

void ThresholdPanel::syncEditor(const QString& key)
{
    QWidget* editor = editors_.value(key);
    if (!editor) return;
    if (typing_.contains(key) && editor->hasFocus()) return;  // follows when editing finishes
    typing_.remove(key);
    const ConfigValue value = doc_->value(key);
    const QSignalBlocker blocker(editor);
    if (auto* spin = qobject_cast<QSpinBox*>(editor)) {
        spin->setValue(std::get<int>(value));
    } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(editor)) {
        dspin->setValue(std::get<double>(value));
    } else if (auto* check = qobject_cast<QCheckBox*>(editor)) {
        check->setChecked(std::get<bool>(value));
    } else if (auto* combo = qobject_cast<QComboBox*>(editor); combo && combo->property("colourClassNames").toBool()) {
        fillClassNames(combo, std::get<std::string>(value));
    } else if (auto* combo = qobject_cast<QComboBox*>(editor)) {
        combo->setCurrentIndex(combo->findData(qs(std::get<std::string>(value))));
    } else if (auto* line = qobject_cast<QLineEdit*>(editor)) {
        if (const auto* list = std::get_if<std::vector<double>>(&value))
            line->setText(formatList(*list));
        else
            line->setText(qs(std::get<std::string>(value)));
        setInvalid(line, false);
    }
}

void ThresholdPanel::fillClassNames(QComboBox* combo, const std::string& current)
{
    combo->clear();
    combo->addItem(tr("none (no hint)"), QStringLiteral("none"));
    bool found = current == "none";
    for (const ColourClassDef& c : doc_->config().colors.classes) {
        if (c.role == ColourRole::Field) continue;  // the ball is never carpet (checkConfig)
        combo->addItem(QStringLiteral("%1 (%2)").arg(qs(c.name), qs(std::string(colourRoleName(c.role)))), qs(c.name));
        found = found || c.name == current;
    }
    if (!found) combo->addItem(tr("%1 (no such class)").arg(qs(current)), qs(current));
    combo->setCurrentIndex(combo->findData(qs(current)));
}

void ThresholdPanel::setInvalid(QWidget* editor, bool invalid)
{
    if (!editor || editor->property("invalid").toBool() == invalid) return;
    editor->setProperty("invalid", invalid);
    editor->setStyleSheet(invalid ? QStringLiteral("QLineEdit { border: 2px solid #d00000; }") : QString());
}

void ThresholdPanel::setStatus(const QString& message)
{
    status_->setText(message);
    status_->setVisible(!message.isEmpty());
}

}  // namespace omnitune
