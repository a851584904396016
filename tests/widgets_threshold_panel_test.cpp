// The threshold panel, driven like a user drives it: keys typed into its spin boxes and line
// edit, clicks on its check boxes, choices in its combo box; every edit must reach the
// ConfigDocument as one undoable change, refused edits must leave the config alone and say why,
// and document changes (undo, load) must show up in the editors.
#include "widgets/ConfigDocument.h"
#include "core/ConfigSchema.h"
#include "widgets/ThresholdPanel.h"

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStyleOptionButton>
#include <QTextDocument>
#include <QtTest>
#include <QUndoStack>
#include <QWheelEvent>

#include <memory>

Q_DECLARE_METATYPE(omnitune::Algorithm)

using namespace omnitune;

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

bool inPanelSection(const ConfigKey& k)
{
    for (const QString& section : ThresholdPanel::sections())
        if (qs(k.path).startsWith(section + QLatin1Char('.'))) return true;
    return false;
}

QString plainText(const QString& maybeHtml)
{
    QTextDocument doc;
    doc.setHtml(maybeHtml);
    return doc.toPlainText();
}

QString shown(const QString& key, const ConfigDocument& doc) { return qs(formatConfigValue(doc.value(key))); }

}  // namespace

class ThresholdPanelTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();

    void onlyThresholdSections();
    void editorsFollowSchema_data();
    void editorsFollowSchema();
    void typedValueIsOneUndoableEdit_data();
    void typedValueIsOneUndoableEdit();
    void checkBoxClick();
    void algorithmChoice_data();
    void algorithmChoice();
    void refusedEditReverts_data();
    void refusedEditReverts();
    void areaBoundsText_data();
    void areaBoundsText();
    void documentChangesUpdateEditors();
    void typingSurvivesDocumentChange();
    void wheelNeedsFocus();
    void fitsBesideImagePanes();
    void searchFiltersAsYouType();

private:
    template <class T>
    T* editor(const QString& key)
    {
        return qobject_cast<T*>(panel_->editorFor(key));
    }
    // Select the editor's text, replace it with `text` and press Enter, as a user would.
    void typeInto(QWidget* editor, const QString& text, bool enter = true);

    std::unique_ptr<ConfigDocument> doc_;
    std::unique_ptr<ThresholdPanel> panel_;
};

void ThresholdPanelTest::init()
{
    doc_ = std::make_unique<ConfigDocument>();
    panel_ = std::make_unique<ThresholdPanel>(doc_.get());
    panel_->resize(320, 700);
    panel_->show();
    QVERIFY(QTest::qWaitForWindowActive(panel_.get()));
}

void ThresholdPanelTest::cleanup()
{
    panel_.reset();
    doc_.reset();
}

void ThresholdPanelTest::typeInto(QWidget* editor, const QString& text, bool enter)
{
    QVERIFY(editor);
    editor->setFocus();
    QTRY_VERIFY(editor->hasFocus());
    QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(editor, Qt::Key_Backspace);
    QTest::keyClicks(editor, text);
    if (enter) QTest::keyClick(editor, Qt::Key_Return);
}

void ThresholdPanelTest::onlyThresholdSections()
{
    int shownKeys = 0;
    for (const ConfigKey& k : configSchema()) {
        const bool expected = inPanelSection(k);
        QVERIFY2((panel_->editorFor(qs(k.path)) != nullptr) == expected, k.path.c_str());
        shownKeys += expected;
    }
    QVERIFY(shownKeys >= 25);  // edges 2, hough 6, opencv_hough 8, validation 8, algorithm 1
    QVERIFY(!panel_->editorFor(QStringLiteral("camera.gain")));
}

void ThresholdPanelTest::editorsFollowSchema_data()
{
    QTest::addColumn<QString>("key");
    for (const ConfigKey& k : configSchema())
        if (inPanelSection(k)) QTest::newRow(k.path.c_str()) << qs(k.path);
}

void ThresholdPanelTest::editorsFollowSchema()
{
    QFETCH(QString, key);
    const ConfigKey* k = findConfigKey(key.toStdString());
    QVERIFY(k);
    QWidget* w = panel_->editorFor(key);
    QVERIFY(w);
    QCOMPARE(w->objectName(), key);
    const ConfigValue value = doc_->value(key);
    switch (k->type) {
    case ValueType::Int: {
        auto* spin = qobject_cast<QSpinBox*>(w);
        QVERIFY(spin);
        QCOMPARE(double(spin->minimum()), k->min);
        QCOMPARE(double(spin->maximum()), k->max);
        QCOMPARE(spin->value(), std::get<int>(value));
        break;
    }
    case ValueType::Double: {
        auto* spin = qobject_cast<QDoubleSpinBox*>(w);
        QVERIFY(spin);
        QCOMPARE(spin->minimum(), k->min);
        QCOMPARE(spin->maximum(), k->max);
        QCOMPARE(spin->value(), std::get<double>(value));  // the default is shown exactly
        if (k->unit == "%") QCOMPARE(spin->decimals(), 1);
        break;
    }
    case ValueType::Bool: {
        auto* check = qobject_cast<QCheckBox*>(w);
        QVERIFY(check);
        QCOMPARE(check->isChecked(), std::get<bool>(value));
        break;
    }
    case ValueType::Choice: {
        auto* combo = qobject_cast<QComboBox*>(w);
        QVERIFY(combo);
        QCOMPARE(combo->count(), int(k->choices.size()));
        for (int i = 0; i < combo->count(); ++i) QCOMPARE(combo->itemText(i), qs(k->choices[std::size_t(i)]));
        QCOMPARE(combo->currentText(), qs(std::get<std::string>(value)));
        break;
    }
    case ValueType::DoubleList: {
        auto* line = qobject_cast<QLineEdit*>(w);
        QVERIFY(line);
        QCOMPARE(QStringLiteral("[%1]").arg(line->text()), shown(key, *doc_));
        break;
    }
    case ValueType::Text: {
        // validation.ball_hint_class names a class of colors.classes, a list the schema's choices
        // cannot hold: a combo box of "none" and the classes that are not field classes.
        QCOMPARE(key, QStringLiteral("validation.ball_hint_class"));
        auto* combo = qobject_cast<QComboBox*>(w);
        QVERIFY(combo);
        QCOMPARE(combo->currentData().toString(), qs(std::get<std::string>(value)));
        QCOMPARE(combo->itemData(0).toString(), QStringLiteral("none"));
        int notField = 0;
        for (const ColourClassDef& c : doc_->config().colors.classes) notField += c.role != ColourRole::Field ? 1 : 0;
        QCOMPARE(combo->count(), 1 + notField);
        break;
    }
    }
    const QString tip = plainText(w->toolTip());
    QVERIFY2(tip.contains(qs(k->meaning)), qPrintable(tip));
    QVERIFY2(tip.contains(key), qPrintable(tip));
    if (k->type == ValueType::Int || k->type == ValueType::Double)
        QVERIFY2(tip.contains(QString::number(k->max, 'g', 10)) && tip.contains(qs(k->unit)), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("Default")), qPrintable(tip));

    // The row's label: short name (and unit), the full key in its tooltip.
    auto* form = qobject_cast<QFormLayout*>(w->parentWidget()->layout());
    QVERIFY(form);
    auto* label = qobject_cast<QLabel*>(form->labelForField(w));
    QVERIFY(label);
    const QString labelText = plainText(label->text()).remove(QChar(0x2060));  // word joiners keep the unit whole
    QVERIFY(!labelText.isEmpty());
    if (!k->unit.empty()) QVERIFY2(labelText.endsWith(QStringLiteral("(%1)").arg(qs(k->unit))), qPrintable(labelText));
    QVERIFY(plainText(label->toolTip()).contains(key));
}

void ThresholdPanelTest::typedValueIsOneUndoableEdit_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("typed");
    QTest::addColumn<QString>("expected");  // formatConfigValue of the new value
    QTest::newRow("canny_high") << "edges.canny_high" << 200.0 << "200";
    QTest::newRow("min_accumulator") << "hough.min_accumulator" << 55.0 << "55";
    QTest::newRow("near_robot_radius") << "hough.near_robot_radius" << 80.5 << "80.5";
    QTest::newRow("dp") << "opencv_hough.dp" << 1.5 << "1.5";
    QTest::newRow("circularity %") << "validation.min_circularity_pct" << 65.5 << "65.5";
    QTest::newRow("radius tolerance") << "validation.radius_tolerance" << 0.2 << "0.2";
}

void ThresholdPanelTest::typedValueIsOneUndoableEdit()
{
    QFETCH(QString, key);
    QFETCH(double, typed);
    QFETCH(QString, expected);
    auto* spin = qobject_cast<QAbstractSpinBox*>(panel_->editorFor(key));
    QVERIFY(spin);
    const QString before = spin->text();
    const QString beforeValue = shown(key, *doc_);
    QVERIFY(beforeValue != expected);

    typeInto(spin, spin->locale().toString(typed));
    QCOMPARE(shown(key, *doc_), expected);
    QCOMPARE(doc_->undoStack()->count(), 1);
    QVERIFY(doc_->undoStack()->text(0).startsWith(key));
    QVERIFY(panel_->statusMessage().isEmpty());
    const QString after = spin->text();
    QVERIFY(after != before);

    // Undo and redo show in the editor, although it still has the focus.
    QVERIFY(spin->hasFocus());
    doc_->undoStack()->undo();
    QCOMPARE(shown(key, *doc_), beforeValue);
    QCOMPARE(spin->text(), before);
    doc_->undoStack()->redo();
    QCOMPARE(spin->text(), after);
    QCOMPARE(doc_->undoStack()->count(), 1);
}

void ThresholdPanelTest::checkBoxClick()
{
    const QString key = QStringLiteral("hough.multiple_maxima");
    auto* check = editor<QCheckBox>(key);
    QVERIFY(check);
    const bool before = doc_->config().hough.multipleMaxima;
    QCOMPARE(check->isChecked(), before);

    QStyleOptionButton option;
    option.initFrom(check);
    const QRect indicator = check->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, check);
    QTest::mouseClick(check, Qt::LeftButton, Qt::NoModifier, indicator.center());
    QCOMPARE(doc_->config().hough.multipleMaxima, !before);
    QCOMPARE(check->isChecked(), !before);
    QCOMPARE(doc_->undoStack()->count(), 1);

    doc_->undoStack()->undo();
    QCOMPARE(doc_->config().hough.multipleMaxima, before);
    QCOMPARE(check->isChecked(), before);

    QTest::keyClick(check, Qt::Key_Space);  // the keyboard works as well
    QCOMPARE(doc_->config().hough.multipleMaxima, !before);
}

void ThresholdPanelTest::algorithmChoice_data()
{
    QTest::addColumn<int>("upPresses");  // from the default, combined (the last entry)
    QTest::addColumn<Algorithm>("expected");
    QTest::newRow("opencv") << 1 << Algorithm::OpenCv;
    QTest::newRow("specific") << 2 << Algorithm::Specific;
}

void ThresholdPanelTest::algorithmChoice()
{
    QFETCH(int, upPresses);
    QFETCH(Algorithm, expected);
    auto* combo = editor<QComboBox>(QStringLiteral("algorithm.method"));
    QVERIFY(combo);
    QCOMPARE(doc_->config().algorithm, Algorithm::Combined);
    QCOMPARE(combo->currentText(), QStringLiteral("combined"));

    // Open the list as a user does (F4), move in it, confirm with Enter.
    combo->setFocus();
    QTRY_VERIFY(combo->hasFocus());
    QTest::keyClick(combo, Qt::Key_F4);
    QTRY_VERIFY(combo->view()->isVisible());
    for (int i = 0; i < upPresses; ++i) QTest::keyClick(combo->view(), Qt::Key_Up);
    QTest::keyClick(combo->view(), Qt::Key_Return);
    QTRY_VERIFY(!combo->view()->isVisible());

    QCOMPARE(doc_->config().algorithm, expected);
    QCOMPARE(doc_->undoStack()->count(), 1);
    doc_->undoStack()->undo();
    QCOMPARE(doc_->config().algorithm, Algorithm::Combined);
    QCOMPARE(combo->currentText(), QStringLiteral("combined"));
}

void ThresholdPanelTest::refusedEditReverts_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("typed");
    QTest::addColumn<QString>("because");
    QTest::newRow("canny_low above canny_high") << "edges.canny_low" << 250 << "is above canny_high";
    QTest::newRow("canny_high below canny_low") << "edges.canny_high" << 40 << "is above canny_high";
    QTest::newRow("opencv min_radius above max") << "opencv_hough.min_radius" << 150 << "min_radius is above max_radius";
}

void ThresholdPanelTest::refusedEditReverts()
{
    QFETCH(QString, key);
    QFETCH(int, typed);
    QFETCH(QString, because);
    auto* spin = editor<QSpinBox>(key);
    QVERIFY(spin);
    QVERIFY(typed >= spin->minimum() && typed <= spin->maximum());  // refused by the document, not the range
    const int before = std::get<int>(doc_->value(key));
    QSignalSpy refused(panel_.get(), &ThresholdPanel::editRefused);
    auto* status = panel_->findChild<QLabel*>(QStringLiteral("status"));
    QVERIFY(status);
    QVERIFY(!status->isVisible());

    typeInto(spin, QString::number(typed));
    QCOMPARE(std::get<int>(doc_->value(key)), before);
    QCOMPARE(doc_->undoStack()->count(), 0);
    QCOMPARE(spin->value(), before);
    QCOMPARE(spin->text(), QString::number(before));
    QCOMPARE(refused.count(), 1);
    const QString message = refused.at(0).at(0).toString();
    QVERIFY2(message.contains(because), qPrintable(message));
    QCOMPARE(panel_->statusMessage(), message);
    QVERIFY(status->isVisible());
    QCOMPARE(status->text(), message);

    // The next accepted edit clears the message.
    QTest::keyClick(editor<QSpinBox>(QStringLiteral("hough.near_robot_weight")), Qt::Key_Up);
    QCOMPARE(doc_->undoStack()->count(), 1);
    QVERIFY(panel_->statusMessage().isEmpty());
    QVERIFY(!status->isVisible());
}

void ThresholdPanelTest::areaBoundsText_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<bool>("accepted");
    QTest::addColumn<QString>("expected");  // accepted: the config's value; refused: part of the message
    QTest::newRow("commas") << "60, 100, 150, 200" << true << "[60, 100, 150, 200]";
    QTest::newRow("spaces and semicolons") << "60 100;150.5" << true << "[60, 100, 150.5]";
    QTest::newRow("not a number") << "70, 1o5, 140" << false << "\"1o5\" is not a number";
    QTest::newRow("empty") << "" << false << "at least one number";
    QTest::newRow("not increasing") << "70, 140, 105" << false << "strictly increasing";
    QTest::newRow("outside the range") << "0, 70" << false << "outside";
}

void ThresholdPanelTest::areaBoundsText()
{
    QFETCH(QString, typed);
    QFETCH(bool, accepted);
    QFETCH(QString, expected);
    const QString key = QStringLiteral("hough.area_bounds");
    auto* line = editor<QLineEdit>(key);
    QVERIFY(line);
    const QString before = shown(key, *doc_);
    const QString beforeText = line->text();
    QSignalSpy refused(panel_.get(), &ThresholdPanel::editRefused);

    typeInto(line, typed);
    if (accepted) {
        QCOMPARE(shown(key, *doc_), expected);
        QCOMPARE(doc_->undoStack()->count(), 1);
        QCOMPARE(QStringLiteral("[%1]").arg(line->text()), expected);  // shown in one canonical form
        QVERIFY(!line->property("invalid").toBool());
        QCOMPARE(refused.count(), 0);
        doc_->undoStack()->undo();
        QCOMPARE(line->text(), beforeText);
    } else {
        QCOMPARE(shown(key, *doc_), before);
        QCOMPARE(doc_->undoStack()->count(), 0);
        QCOMPARE(line->text(), typed);  // kept, to be corrected
        QVERIFY(line->property("invalid").toBool());
        QVERIFY(line->styleSheet().contains(QStringLiteral("border")));
        QCOMPARE(refused.count(), 1);
        QVERIFY2(panel_->statusMessage().contains(expected), qPrintable(panel_->statusMessage()));
        QVERIFY(panel_->statusMessage().contains(key));
        // Loading a config puts the document's value back and clears the mark.
        line->clearFocus();
        doc_->reset(Config{});
        QCOMPARE(line->text(), beforeText);
        QVERIFY(!line->property("invalid").toBool());
        QVERIFY(line->styleSheet().isEmpty());
    }
}

void ThresholdPanelTest::documentChangesUpdateEditors()
{
    Config c;
    c.edges.cannyHigh = 222;
    c.hough.multipleMaxima = !c.hough.multipleMaxima;
    c.hough.areaBounds = {80, 160, 240};
    c.algorithm = Algorithm::Specific;
    c.validation.radiusTolerance = 0.12345;  // finer than the editor shows
    c.validation.minNonGreenPct = 80.25;
    QSignalSpy changed(doc_.get(), &ConfigDocument::changed);
    doc_->reset(c);
    QCOMPARE(changed.count(), 1);  // only the load itself: the editors did not edit back

    QCOMPARE(editor<QSpinBox>(QStringLiteral("edges.canny_high"))->value(), 222);
    QCOMPARE(editor<QCheckBox>(QStringLiteral("hough.multiple_maxima"))->isChecked(), c.hough.multipleMaxima);
    QCOMPARE(editor<QLineEdit>(QStringLiteral("hough.area_bounds"))->text(), QStringLiteral("80, 160, 240"));
    QCOMPARE(editor<QComboBox>(QStringLiteral("algorithm.method"))->currentText(), QStringLiteral("specific"));
    QCOMPARE(editor<QDoubleSpinBox>(QStringLiteral("validation.radius_tolerance"))->value(), 0.123);
    QCOMPARE(doc_->config().validation.radiusTolerance, 0.12345);  // not rounded by the editor
    QCOMPARE(doc_->undoStack()->count(), 0);
    QVERIFY(!doc_->isDirty());

    // Committing the rounded text unchanged (Enter) does not round the config either.
    auto* nonGreen = editor<QDoubleSpinBox>(QStringLiteral("validation.min_non_green_pct"));
    nonGreen->setFocus();
    QTRY_VERIFY(nonGreen->hasFocus());
    QTest::keyClick(nonGreen, Qt::Key_Return);
    QCOMPARE(doc_->config().validation.minNonGreenPct, 80.25);
    QCOMPARE(doc_->undoStack()->count(), 0);

    // A change made elsewhere (another editor, a script) shows up as well.
    QVERIFY(!doc_->setValue(QStringLiteral("opencv_hough.max_circles"), 7));
    QCOMPARE(editor<QSpinBox>(QStringLiteral("opencv_hough.max_circles"))->value(), 7);
}

void ThresholdPanelTest::typingSurvivesDocumentChange()
{
    const QString key = QStringLiteral("edges.canny_high");
    auto* spin = editor<QSpinBox>(key);
    auto* other = editor<QSpinBox>(QStringLiteral("edges.canny_low"));
    QVERIFY(spin && other);
    QVERIFY(!doc_->setValue(key, 200));
    QCOMPARE(spin->value(), 200);

    // Typed text is not overwritten by an undo; leaving the editor commits it.
    typeInto(spin, QStringLiteral("190"), false);
    doc_->undoStack()->undo();
    QCOMPARE(doc_->config().edges.cannyHigh, 180);
    QCOMPARE(spin->text(), QStringLiteral("190"));
    other->setFocus();
    QTRY_VERIFY(!spin->hasFocus());
    QCOMPARE(doc_->config().edges.cannyHigh, 190);
    QCOMPARE(spin->text(), QStringLiteral("190"));

    // Text that is no number is not overwritten either; on leaving, the editor shows the
    // document's value (not the one it had before the user started typing).
    typeInto(spin, QString(), false);
    QCOMPARE(spin->text(), QString());
    QVERIFY(!doc_->setValue(key, 300));
    QCOMPARE(spin->text(), QString());
    other->setFocus();
    QTRY_VERIFY(!spin->hasFocus());
    QCOMPARE(spin->value(), 300);
    QCOMPARE(spin->text(), QStringLiteral("300"));
    QCOMPARE(doc_->config().edges.cannyHigh, 300);
}

void ThresholdPanelTest::wheelNeedsFocus()
{
    auto* spin = editor<QSpinBox>(QStringLiteral("edges.canny_low"));
    QVERIFY(spin);
    const QPoint centre = spin->rect().center();
    auto turn = [&] {
        QWheelEvent wheel(centre, spin->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(spin, &wheel);
    };
    QVERIFY(!spin->hasFocus());
    turn();  // scrolling the panel over an editor
    QCOMPARE(doc_->config().edges.cannyLow, 60);
    QCOMPARE(doc_->undoStack()->count(), 0);

    spin->setFocus();
    QTRY_VERIFY(spin->hasFocus());
    turn();
    QCOMPARE(doc_->config().edges.cannyLow, 61);
    QCOMPARE(doc_->undoStack()->count(), 1);
}

void ThresholdPanelTest::fitsBesideImagePanes()
{
    // A 1366x768 laptop with the five image panes beside it: narrow, and scrolls vertically.
    QVERIFY2(panel_->minimumSizeHint().width() <= 360, qPrintable(QString::number(panel_->minimumSizeHint().width())));
    QVERIFY2(panel_->minimumSizeHint().height() <= 300, qPrintable(QString::number(panel_->minimumSizeHint().height())));
    auto* scroll = panel_->findChild<QScrollArea*>();
    QVERIFY(scroll);
    panel_->resize(panel_->minimumSizeHint().width(), 600);
    QTRY_COMPARE(panel_->height(), 600);
    QVERIFY(scroll->verticalScrollBar()->maximum() > 0);
    QVERIFY(!scroll->horizontalScrollBar()->isVisible());
}

void ThresholdPanelTest::searchFiltersAsYouType()
{
    // A short panel (a 1366x768 screen): the validation group is below the fold until searched.
    panel_->resize(320, 400);
    QTRY_COMPARE(panel_->height(), 400);
    auto* scroll = panel_->findChild<QScrollArea*>();
    QWidget* circularity = panel_->editorFor("validation.min_circularity_pct");
    QWidget* canny = panel_->editorFor("edges.canny_low");
    QVERIFY(circularity && canny);
    const auto inView = [scroll](QWidget* w) {
        if (!w->isVisible()) return false;
        const QRect r(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
        return scroll->viewport()->rect().contains(r);
    };
    QVERIFY(!inView(circularity));
    QVERIFY(inView(canny));

    QLineEdit* search = panel_->searchBox();
    QVERIFY(search && search->isVisible());
    search->setFocus();
    QTest::keyClicks(search, "circ");  // filters as the user types: no Enter
    QTRY_VERIFY(inView(circularity));
    QVERIFY(!canny->isVisible());
    // Every editor still shown matches; the Canny group has none left and goes.
    for (const ConfigKey& k : configSchema()) {
        QWidget* e = panel_->editorFor(qs(k.path));
        if (!e) continue;
        const QString label = plainText(qobject_cast<QLabel*>(qobject_cast<QFormLayout*>(e->parentWidget()->layout())
                                                                  ->labelForField(e))->text());
        QCOMPARE(e->isVisible(), qs(k.path).contains("circ") || label.toLower().contains("circ"));
    }
    QVERIFY(!canny->parentWidget()->isVisible());
    QVERIFY(!panel_->findChild<QLabel*>("noMatch")->isVisible());

    // A group's name finds all of its rows; words combine.
    search->clear();
    QTest::keyClicks(search, "validation black");
    QTRY_VERIFY(panel_->editorFor("validation.min_non_black_pct")->isVisible());
    QVERIFY(!circularity->isVisible());

    // Nothing matches: the panel says so. Escape clears and everything comes back.
    search->clear();
    QTest::keyClicks(search, "zzz");
    QTRY_VERIFY(panel_->findChild<QLabel*>("noMatch")->isVisible());
    QVERIFY(panel_->findChild<QLabel*>("noMatch")->text().contains("zzz"));
    QTest::keyClick(search, Qt::Key_Escape);
    QCOMPARE(search->text(), QString());
    QTRY_VERIFY(canny->isVisible());
    QVERIFY(circularity->isVisible());
    QVERIFY(!panel_->findChild<QLabel*>("noMatch")->isVisible());
    QCOMPARE(doc_->undoStack()->count(), 0);  // searching edits nothing
}

QTEST_MAIN(ThresholdPanelTest)
#include "widgets_threshold_panel_test.moc"
