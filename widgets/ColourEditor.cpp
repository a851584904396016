#include "widgets/ColourEditor.h"

#include "calib/colour/AutoColour.h"
#include "calib/colour/ClassView.h"
#include "calib/colour/HsvHistogram.h"
#include "calib/colour/HsvImage.h"
#include "core/Geometry.h"
#include "widgets/ColourBoxEditor.h"
#include "widgets/ColourClassList.h"
#include "widgets/ColourPlaneView.h"
#include "widgets/ColourProfilesBox.h"
#include "widgets/ColourSampler.h"
#include "widgets/ColourSamplingBox.h"
#include "widgets/ColourSwatch.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/PipelineView.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace omnitune {

namespace {

QString boxLabel(int i, const HsvRange& b)
{
    return QObject::tr("Box %1: H %2..%3%4, S %5..%6, V %7..%8%9")
        .arg(i + 1).arg(b.hMin).arg(b.hMax).arg(b.hMin > b.hMax ? QObject::tr(" (wraps)") : QString())
        .arg(b.sMin).arg(b.sMax).arg(b.vMin).arg(b.vMax).arg(b.enabled ? QString() : QObject::tr(" (off)"));
}

// Display colours for new classes, distinct from the default classes' ones.
const std::array<std::uint8_t, 3> kNewClassColours[] = {
    {0, 200, 255}, {255, 100, 0}, {180, 0, 180}, {0, 100, 200}, {200, 200, 0}, {100, 0, 255}, {0, 255, 150}};

ClassBoxes boxesOf(const ColourClasses& classes)
{
    ClassBoxes out;
    for (const ColourClassDef& c : classes) out.push_back(c.enabled ? c.boxes : std::vector<HsvRange>{});
    return out;
}


}  // namespace

ColourEditor::ColourEditor(ConfigDocument* doc, PipelineView* view, QWidget* parent)
    : QWidget(parent), doc_(doc), view_(view), sampler_(new ColourSampler(doc, view, this)),
      classList_(new ColourClassList), boxList_(new QListWidget), boxEditor_(new ColourBoxEditor), plane_(new ColourPlaneView), name_(new QLineEdit),
      role_(new QComboBox), display_(new QPushButton), onlyThis_(new QCheckBox(tr("Show only this class"))),
      overlaps_(new QCheckBox(tr("Flag pixels two classes claim"))), sharesLabel_(new QLabel),
      profiles_(new ColourProfilesBox(doc))
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName("colourScroll");
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the rows shrink to the dock's width
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto* inner = new QWidget(scroll);
    scroll->setWidget(inner);
    auto* layout = new QVBoxLayout(inner);
    layout->setContentsMargins(4, 4, 4, 4);

    layout->addWidget(new ColourSamplingBox(doc_, sampler_, inner));
    layout->addWidget(classList_);

    // The selected class.
    auto* classBox = new QGroupBox(tr("Selected class"), inner);
    auto* form = new QFormLayout(classBox);
    name_->setObjectName("className");
    name_->setToolTip(tr("Lower case a-z first, then a-z, 0-9 and _; unique"));
    form->addRow(tr("Name"), name_);
    role_->setObjectName("classRole");
    for (ColourRole r : kColourRoles) role_->addItem(QString::fromUtf8(colourRoleName(r).data(), int(colourRoleName(r).size())));
    role_->setToolTip(tr("What the detector uses the class for: field (carpet; several classes may be field), line, "
                         "black (robots, shadows), ball, marker or other"));
    form->addRow(tr("Role"), role_);
    display_->setObjectName("displayColour");
    display_->setToolTip(tr("The class's colour on the segmented pane"));
    form->addRow(tr("Shown as"), display_);
    boxList_->setObjectName("boxList");
    boxList_->setMaximumHeight(80);
    boxList_->setToolTip(tr("The class is the union of its boxes (a carpet under vignetting may need more than one); "
                            "strokes grow the selected box"));
    form->addRow(boxList_);
    auto* boxButtons = new QHBoxLayout;
    QPushButton* addBoxButton = colourTabButton(tr("Add box"), tr("A new box: the next stroke makes it"), "addBox", classBox);
    QPushButton* removeBoxButton = colourTabButton(tr("Remove box"), tr("Remove the selected box (a class keeps one at least)"),
                                               "removeBox", classBox);
    boxButtons->addWidget(addBoxButton);
    boxButtons->addWidget(removeBoxButton);
    form->addRow(boxButtons);
    form->addRow(boxEditor_);
    layout->addWidget(classBox);

    // The frame's colours on the H-S plane, with the boxes to drag.
    auto* planeBox = new QGroupBox(tr("H-S plane and V histogram of this frame"), inner);
    auto* pl = new QVBoxLayout(planeBox);
    plane_->setObjectName("planeView");
    pl->addWidget(plane_);
    layout->addWidget(planeBox);

    // What the frame on screen looks like with these classes.
    auto* viewBox = new QGroupBox(tr("Segmented pane"), inner);
    auto* vl = new QVBoxLayout(viewBox);
    onlyThis_->setObjectName("onlyThisClass");
    overlaps_->setObjectName("flagOverlaps");
    overlaps_->setToolTip(tr("Red and white stripes where the boxes of two or more classes hold the pixel's colour: "
                             "the class higher in the list gets it"));
    sharesLabel_->setObjectName("shares");
    sharesLabel_->setWordWrap(false);  // two short lines: a wrapped label in a scroll area may be cut
    vl->addWidget(onlyThis_);
    vl->addWidget(overlaps_);
    vl->addWidget(sharesLabel_);
    layout->addWidget(viewBox);
    layout->addWidget(profiles_);
    layout->addStretch(1);

    connect(sampler_, &ColourSampler::message, this, &ColourEditor::message);
    connect(profiles_, &ColourProfilesBox::message, this, &ColourEditor::message);
    connect(sampler_, &ColourSampler::targetEdited, this, [this](int c, int box) {
        wantClass_ = c;
        wantBox_ = std::max(0, box);
        refresh();
    });

    auto report = [this](const std::optional<QString>& why) {
        if (why) emit message(*why);
    };
    connect(classList_, &ColourClassList::addRequested, this, [this, report] { report(addClass()); });
    connect(classList_, &ColourClassList::removeRequested, this, [this, report] { report(removeClass()); });
    connect(classList_, &ColourClassList::moveRequested, this, [this, report](int delta) { report(moveClass(delta)); });
    connect(classList_, &ColourClassList::autoRequested, this, [this, report] { report(autoColours()); });
    connect(addBoxButton, &QPushButton::clicked, this, [this, report] { report(addBox()); });
    connect(removeBoxButton, &QPushButton::clicked, this, [this, report] { report(removeBox()); });
    connect(name_, &QLineEdit::editingFinished, this, [this, report] {
        if (refreshing_ || currentClass() < 0) return;
        if (name_->text().toStdString() == classes()[std::size_t(currentClass())].name) return;
        const auto why = renameClass(name_->text());
        report(why);
        if (why) refresh();  // back to the name the class has
    });
    connect(role_, QOverload<int>::of(&QComboBox::activated), this,
            [this, report](int i) { report(setRole(kColourRoles[std::size_t(i)])); });
    connect(display_, &QPushButton::clicked, this, [this, report] {
        if (currentClass() < 0) return;
        const QColor now = toQColor(classes()[std::size_t(currentClass())].display);
        const QColor c = QColorDialog::getColor(now, this, tr("Colour of the class on the segmented pane"));
        if (c.isValid()) report(setDisplayColour(c));
    });
    connect(classList_, &ColourClassList::currentChanged, this, [this](int row) {
        if (refreshing_) return;
        wantClass_ = row;
        wantBox_ = 0;
        refresh();
        updateView();
    });
    connect(classList_, &ColourClassList::enabledChanged, this, [this, report](int row, bool on) {
        if (!refreshing_) report(setClassEnabled(row, on));
    });
    connect(boxList_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (refreshing_ || row < 0) return;
        wantBox_ = row;
        refresh();
    });
    connect(boxEditor_, &ColourBoxEditor::edited, this, &ColourEditor::onBoxEdited);
    connect(plane_, &ColourPlaneView::edited, this, &ColourEditor::onBoxEdited);
    connect(onlyThis_, &QCheckBox::toggled, this, [this] { updateView(); });
    connect(overlaps_, &QCheckBox::toggled, this, [this] { updateView(); });
    connect(doc_, &ConfigDocument::changed, this, [this] {
        if (!dragging_) refresh();  // a drag's live values are the sliders' own
    });
    refresh();
}

QListWidget* ColourEditor::classList() const { return classList_->list(); }

const ColourClasses& ColourEditor::classes() const { return doc_->config().colors.classes; }

int ColourEditor::currentClass() const
{
    const int n = int(classes().size());
    return n == 0 ? -1 : std::clamp(wantClass_, 0, n - 1);
}

int ColourEditor::currentBox() const
{
    const int c = currentClass();
    if (c < 0) return -1;
    const int n = int(classes()[std::size_t(c)].boxes.size());
    return n == 0 ? -1 : std::clamp(wantBox_, 0, n - 1);
}

void ColourEditor::selectClass(int index)
{
    wantClass_ = index;
    wantBox_ = 0;
    refresh();
    updateView();
}

void ColourEditor::selectBox(int index)
{
    wantBox_ = index;
    refresh();
}

void ColourEditor::fillMenu(QMenu* menu)
{
    sampler_->fillMenu(menu);
    menu->addSeparator();
    QAction* a = menu->addAction(tr("&Auto colours from this frame"), this, [this] {
        if (const auto why = autoColours()) emit message(*why);
    });
    a->setObjectName("autoColoursAction");
}

void ColourEditor::syncTarget() { sampler_->setTarget(currentClass(), currentBox()); }

void ColourEditor::refresh()
{
    refreshing_ = true;
    const ColourClasses& cs = classes();
    const int c = currentClass();
    classList_->setClasses(cs, c);
    refreshShares();
    {
        const QSignalBlocker block(boxList_);
        boxList_->clear();
        if (c >= 0) {
            const auto& boxes = cs[std::size_t(c)].boxes;
            for (std::size_t i = 0; i < boxes.size(); ++i) boxList_->addItem(boxLabel(int(i), boxes[i]));
        }
        boxList_->setCurrentRow(currentBox());
    }
    if (c >= 0) {
        const ColourClassDef& def = cs[std::size_t(c)];
        if (!name_->hasFocus()) name_->setText(QString::fromStdString(def.name));
        role_->setCurrentIndex(int(std::find(kColourRoles.begin(), kColourRoles.end(), def.role) - kColourRoles.begin()));
        display_->setIcon(colourSwatch(toQColor(def.display)));
        display_->setText(toQColor(def.display).name());
    }
    const int b = currentBox();
    boxEditor_->setEnabled(b >= 0);
    if (b >= 0) boxEditor_->setBox(cs[std::size_t(c)].boxes[std::size_t(b)]);
    plane_->setClasses(cs, c, b);
    syncTarget();
    refreshing_ = false;
}

void ColourEditor::refreshShares()
{
    const ColourClasses& cs = classes();
    const bool have = shares_.processed > 0 && shares_.counts.size() == cs.size();
    classList_->setShares(cs, have ? &shares_ : nullptr);
    sharesLabel_->setText(have ? tr("Frame %1: %2 of the processed pixels in no class,\n%3 claimed by two or more "
                                    "classes (%4 px)")
                                     .arg(run_ ? run_->frameIndex : -1)
                                     .arg(colourSharePct(shares_.pct(shares_.unclassified)))
                                     .arg(colourSharePct(shares_.pct(shares_.overlapCount)))
                                     .arg(shares_.overlapCount)
                               : tr("Shares appear with a processed frame"));
}

void ColourEditor::setRun(std::shared_ptr<const PipelineRun> run)
{
    run_ = std::move(run);
    sampler_->setRun(run_);
    profiles_->setRun(run_);
    analysed_ = false;
    if (isVisible()) analyse();
}

void ColourEditor::analyse()
{
    analysed_ = true;
    shares_ = ClassShares{};
    runHsv_.release();
    runUsed_.release();
    const bool processed = run_ && run_->error.isEmpty() && run_->result.ok() && !run_->frame.empty() &&
                           run_->frame.size() == cv::Size(run_->config.geometry.imageWidth, run_->config.geometry.imageHeight);
    if (processed) {
        runHsv_ = hsvImage(run_->frame, run_->format);
        runUsed_ = Geometry(run_->config.geometry, run_->config.mask).usedMask();
        shares_ = classShares(runHsv_, runUsed_, boxesOf(run_->config.colors.classes));
        if (run_->result.classes.size() == run_->frame.size()) countSegmented(shares_, run_->result.classes, runUsed_);
        const HsvHistogram h = hsvHistogram(runHsv_, runUsed_);
        plane_->setHistogram(toQImage(hsPlaneImage(h)), h.v);
    } else {
        plane_->setHistogram(QImage(), {});
    }
    refreshShares();
    updateView();
}

void ColourEditor::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (!analysed_) analyse();
    else updateView();
}

void ColourEditor::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    if (run_ && run_->result.ok() && !run_->result.stages.segmented.empty())
        view_->pane(PipelineView::Segmented)->setImage(toQImage(run_->result.stages.segmented));
}

void ColourEditor::setOnlyThisClass(bool on) { onlyThis_->setChecked(on); }
void ColourEditor::setFlagOverlaps(bool on) { overlaps_->setChecked(on); }

void ColourEditor::updateView()
{
    if (!run_ || !run_->result.ok() || run_->result.stages.segmented.empty() || run_->result.classes.empty()) return;
    ClassViewOptions o;
    o.onlyClass = onlyThis_->isChecked() && currentClass() >= 0 ? int(colourClassId(currentClass())) : -1;
    o.flagOverlaps = overlaps_->isChecked();
    const cv::Mat& segmented = run_->result.stages.segmented;
    view_->pane(PipelineView::Segmented)
        ->setImage(toQImage(o.onlyClass < 0 && !o.flagOverlaps ? segmented
                                                                 : classView(segmented, run_->result.classes, shares_.overlap, o)));
}

std::optional<QString> ColourEditor::commit(const Config& next, const QString& text)
{
    const auto why = doc_->replaceConfig(next, text);
    if (why) refresh();  // the widgets go back to what the document holds
    return why;
}

std::optional<QString> ColourEditor::editClass(const QString& text, const std::function<void(ColourClassDef&)>& edit)
{
    const int c = currentClass();
    if (c < 0) return tr("No class selected");
    Config next = doc_->config();
    edit(next.colors.classes[std::size_t(c)]);
    return commit(next, text.arg(QString::fromStdString(next.colors.classes[std::size_t(c)].name)));
}

std::optional<QString> ColourEditor::addClass()
{
    Config next = doc_->config();
    ColourClasses& cs = next.colors.classes;
    if (int(cs.size()) >= kMaxColourClasses)
        return tr("At most %1 colour classes (the segmented image keeps class ids in 4 bits)").arg(kMaxColourClasses);
    ColourClassDef def;
    for (int i = 1;; ++i) {
        def.name = "class_" + std::to_string(i);
        if (findColourClass(cs, def.name) < 0) break;
    }
    def.role = ColourRole::Other;
    def.display = kNewClassColours[cs.size() % std::size(kNewClassColours)];
    HsvRange empty;
    empty.enabled = false;  // matches nothing until the first stroke makes it (growBox)
    def.boxes = {empty};
    cs.push_back(def);
    wantClass_ = int(cs.size()) - 1;
    wantBox_ = 0;
    const auto why = commit(next, tr("Add class %1").arg(QString::fromStdString(def.name)));
    if (!why) emit message(tr("New class %1 at the end of the list: rename it, give it a role and sample into it")
                               .arg(QString::fromStdString(def.name)));
    return why;
}

std::optional<QString> ColourEditor::removeClass()
{
    const int c = currentClass();
    if (c < 0) return tr("No class selected");
    Config next = doc_->config();
    const QString name = QString::fromStdString(next.colors.classes[std::size_t(c)].name);
    next.colors.classes.erase(next.colors.classes.begin() + c);
    return commit(next, tr("Remove class %1").arg(name));
}

std::optional<QString> ColourEditor::moveClass(int delta)
{
    const int c = currentClass();
    const int to = c + delta;
    if (c < 0 || to < 0 || to >= int(classes().size())) return tr("The class is already at that end of the list");
    Config next = doc_->config();
    std::swap(next.colors.classes[std::size_t(c)], next.colors.classes[std::size_t(to)]);
    wantClass_ = to;
    const auto why = commit(next, tr("Move class %1 %2").arg(QString::fromStdString(next.colors.classes[std::size_t(to)].name),
                                                               delta < 0 ? tr("up") : tr("down")));
    if (why) wantClass_ = c;
    return why;
}

std::optional<QString> ColourEditor::renameClass(const QString& name)
{
    const std::string n = name.trimmed().toStdString();
    if (!isValidColourClassName(n))
        return tr("\"%1\" cannot name a class: lower case a-z first, then a-z, 0-9 and _ (not \"unknown\" or \"none\")").arg(name);
    const int other = findColourClass(classes(), n);
    if (other >= 0 && other != currentClass()) return tr("A class named %1 exists already").arg(name);
    // The ball hint names the class by name: it follows the rename in the same undo step.
    const int c = currentClass();
    if (c < 0) return tr("No class selected");
    Config next = doc_->config();
    const std::string old = next.colors.classes[std::size_t(c)].name;
    next.colors.classes[std::size_t(c)].name = n;
    if (next.validation.ballHint == old) next.validation.ballHint = n;
    return commit(next, tr("Rename class %1 to %2").arg(QString::fromStdString(old), name.trimmed()));
}

std::optional<QString> ColourEditor::setRole(ColourRole role)
{
    return editClass(tr("Role of %1: ") + QString::fromUtf8(colourRoleName(role).data()),
                     [&](ColourClassDef& d) { d.role = role; });
}

std::optional<QString> ColourEditor::setDisplayColour(const QColor& colour)
{
    return editClass(tr("Display colour of %1"), [&](ColourClassDef& d) {
        d.display = {std::uint8_t(colour.blue()), std::uint8_t(colour.green()), std::uint8_t(colour.red())};
    });
}

std::optional<QString> ColourEditor::setClassEnabled(int index, bool on)
{
    if (index < 0 || index >= int(classes().size())) return tr("No such class");
    Config next = doc_->config();
    ColourClassDef& d = next.colors.classes[std::size_t(index)];
    if (d.enabled == on) return std::nullopt;
    d.enabled = on;
    return commit(next, (on ? tr("Switch on %1") : tr("Switch off %1")).arg(QString::fromStdString(d.name)));
}

std::optional<QString> ColourEditor::addBox()
{
    const int c = currentClass();
    if (c < 0) return tr("No class selected");
    wantBox_ = int(classes()[std::size_t(c)].boxes.size());
    return editClass(tr("Add a box to %1"), [](ColourClassDef& d) {
        HsvRange empty;
        empty.enabled = false;  // the next stroke makes it
        d.boxes.push_back(empty);
    });
}

std::optional<QString> ColourEditor::removeBox()
{
    const int c = currentClass();
    const int b = currentBox();
    if (b < 0) return tr("No box selected");
    if (classes()[std::size_t(c)].boxes.size() <= 1) return tr("A class needs one box at least: remove the class instead");
    return editClass(tr("Remove a box of %1"), [b](ColourClassDef& d) { d.boxes.erase(d.boxes.begin() + b); });
}

void ColourEditor::onBoxEdited(const HsvRange& edited, bool finished)
{
    const HsvRange box = edited;  // a copy: refreshing the editors below changes what `edited` refers to
    const int c = currentClass();
    const int b = currentBox();
    if (c < 0 || b < 0) return;
    auto withBox = [&](Config cfg) {
        cfg.colors.classes[std::size_t(c)].boxes[std::size_t(b)] = box;
        return cfg;
    };
    if (!finished) {
        // Live while the slider moves: the segmented pane follows, no undo step per position.
        if (!dragging_) dragStart_ = doc_->config();
        dragging_ = true;
        const Config next = withBox(dragStart_);
        if (checkConfig(next).empty()) doc_->applyConfig(next);
        boxEditor_->setBox(box);  // sliders and plane show the drag, whichever of them it is on
        plane_->setClasses(next.colors.classes, c, b);
        return;
    }
    const Config base = dragging_ ? dragStart_ : doc_->config();
    if (dragging_) {
        dragging_ = false;
        doc_->applyConfig(dragStart_);  // the undo step goes from where the drag began
    }
    if (base.colors.classes[std::size_t(c)].boxes[std::size_t(b)] == box) {
        refresh();
        return;
    }
    if (const auto why = commit(withBox(base), tr("Box %1 of %2").arg(b + 1).arg(QString::fromStdString(base.colors.classes[std::size_t(c)].name))))
        emit message(*why);
}

std::optional<QString> ColourEditor::autoColours()
{
    if (!run_ || run_->frame.empty() || !run_->error.isEmpty()) return tr("Auto colours needs a processed frame on screen");
    const Config& cfg = doc_->config();
    const cv::Size size(cfg.geometry.imageWidth, cfg.geometry.imageHeight);
    if (run_->frame.size() != size) return tr("The frame on screen does not fit the config's image size");
    const AutoColourResult r = autoColour({run_->frame}, Geometry(cfg.geometry, cfg.mask), cfg.colors);
    if (!r.ok()) return tr("Auto colours: %1").arg(QString::fromStdString(*r.error));
    Config next = cfg;
    next.colors = r.colors;
    if (const auto why = commit(next, tr("Auto colours from frame %1").arg(run_->frameIndex))) return why;
    QStringList notes;
    for (const auto& n : r.notes) notes << QString::fromStdString(n);
    // Short enough to show whole beside the stage timings (app/colour_done_when checks it).
    emit message(tr("Auto colours: carpet hue %1 (%2 %), median S %3, V %4%5")
                     .arg(r.carpetHue).arg(r.carpetPct, 0, 'f', 0).arg(r.carpetS).arg(r.carpetV)
                     .arg(notes.isEmpty() ? QString() : QStringLiteral("; ") + notes.join(QStringLiteral("; "))));
    return std::nullopt;
}

}  // namespace omnitune
