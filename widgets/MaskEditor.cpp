#include "widgets/MaskEditor.h"

#include "calib/mask/MaskPaint.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PaneInput.h"
#include "widgets/PaneSketch.h"
#include "widgets/PipelineView.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QToolBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <functional>

namespace omnitune {

namespace {

cv::Point2d toCv(QPointF p) { return {p.x(), p.y()}; }

}  // namespace

MaskEditor::MaskEditor(ConfigDocument* doc, PipelineView* view, QObject* parent)
    : QObject(parent), doc_(doc), view_(view)
{
    connectPaneInput(view_, this, &MaskEditor::onPressed, &MaskEditor::onDragged, &MaskEditor::onReleased);
    connect(view_, &PipelineView::hovered, this, [this](QPointF p) {
        cursor_ = p;
        if (editing_) updatePreviews();
    });
    connect(view_, &PipelineView::left, this, [this] {
        cursor_ = QPointF(-1, -1);
        if (editing_) updatePreviews();
    });
    for (int i = 0; i < PipelineView::kPaneCount; ++i) {
        ImageView* pane = view_->pane(i);
        previews_.push_back(new PaneSketch(pane, [this](QPainter& p, const ImageView& v) { paintPreview(p, v); }));
        pane->installEventFilter(this);
    }
    buildToolBar();
}

// The open polygon and the brush under the cursor, over one pane.
void MaskEditor::paintPreview(QPainter& p, const ImageView& pane) const
{
    const bool inside = cursor_.x() >= 0;
    if (!polygon_.empty()) {
        QPolygonF line;
        for (const QPointF& v : polygon_) line << pane.toWidget(v);
        if (inside) line << pane.toWidget(cursor_);
        p.setPen(QPen(Qt::black, 3));
        p.drawPolyline(line);
        p.setPen(QPen(Qt::white, 1, Qt::DashLine));
        p.drawPolyline(line);
        p.setPen(QPen(Qt::white, 1));
        for (const QPointF& v : polygon_) p.drawRect(QRectF(pane.toWidget(v) - QPointF(3, 3), QSizeF(6, 6)));
        p.drawEllipse(pane.toWidget(polygon_.front()), kCloseDistance, kCloseDistance);
    }
    if (inside && (tool_ == Tool::Brush || tool_ == Tool::Eraser)) {
        const double r = radius_ * pane.scale();
        const QPointF c = pane.toWidget(cursor_);
        p.setPen(QPen(Qt::black, 3));
        p.drawEllipse(c, r, r);
        p.setPen(QPen(tool_ == Tool::Brush ? QColor(255, 120, 0) : QColor(Qt::white), 1));
        p.drawEllipse(c, r, r);
    }
}

void MaskEditor::buildToolBar()
{
    toolBar_ = new QToolBar(tr("Mask editor"), view_);
    toolBar_->setObjectName(QStringLiteral("maskToolBar"));
    toolBar_->hide();
    tools_ = new QActionGroup(this);
    const struct {
        Tool tool;
        QString name, tip;
        Qt::Key key;
    } tools[] = {
        {Tool::Brush, tr("Brush"), tr("Paint robot: pixels the detector never looks at"), Qt::Key_B},
        {Tool::Eraser, tr("Eraser"), tr("Give pixels back to the detector (processed)"), Qt::Key_E},
        {Tool::Polygon, tr("Polygon"), tr("Click the vertices; Enter, a double-click or a click on the first vertex fills it"), Qt::Key_P},
        {Tool::Fill, tr("Fill"), tr("Fill the connected region under the click"), Qt::Key_L},
    };
    for (const auto& t : tools) {
        QAction* a = toolBar_->addAction(t.name);
        a->setObjectName(QStringLiteral("maskTool%1").arg(int(t.tool)));
        a->setCheckable(true);
        a->setChecked(t.tool == tool_);
        a->setShortcut(QKeySequence(t.key));
        a->setToolTip(QStringLiteral("%1 (%2)").arg(t.tip, QKeySequence(t.key).toString(QKeySequence::NativeText)));
        a->setData(int(t.tool));
        tools_->addAction(a);
        editingActions_.push_back(a);
        connect(a, &QAction::triggered, this, [this, tool = t.tool] { setTool(tool); });
    }
    toolBar_->addSeparator();
    toolBar_->addWidget(new QLabel(tr(" Brush radius "), toolBar_));
    radiusBox_ = new QDoubleSpinBox(toolBar_);
    radiusBox_->setObjectName(QStringLiteral("maskBrushRadius"));
    radiusBox_->setRange(kMinRadius, kMaxRadius);
    radiusBox_->setSingleStep(kRadiusStep);
    radiusBox_->setDecimals(1);
    radiusBox_->setSuffix(tr(" px"));
    radiusBox_->setValue(radius_);
    radiusBox_->setToolTip(tr("Image px; [ and ] or Ctrl+wheel on a pane change it"));
    connect(radiusBox_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &MaskEditor::setBrushRadius);
    toolBar_->addWidget(radiusBox_);
    toolBar_->addSeparator();
    toolBar_->addWidget(new QLabel(tr(" Polygon and fill paint "), toolBar_));
    areasBox_ = new QComboBox(toolBar_);
    areasBox_->setObjectName(QStringLiteral("maskAreasAs"));
    areasBox_->addItem(tr("robot (not processed)"));
    areasBox_->addItem(tr("processed"));
    areasBox_->setToolTip(tr("X swaps"));
    connect(areasBox_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) { setAreasAsRobot(i == 0); });
    toolBar_->addWidget(areasBox_);
    toolBar_->addSeparator();
    QAction* done = toolBar_->addAction(tr("Done"));
    done->setToolTip(tr("Leave the mask editor (M or Esc); File > Save writes the mask beside the config"));
    connect(done, &QAction::triggered, this, [this] { setEditing(false); });
}

void MaskEditor::fillMenu(QMenu* menu)
{
    modeAction_ = addEditModeAction(menu, this, &MaskEditor::setEditing, tr("Edit &mask on the panes"),
                                    QStringLiteral("editMask"), QKeySequence(Qt::Key_M),
                                    tr("Paint the robot body, rods and reflections out of what the detector processes"));
    QMenu* toolsMenu = menu->addMenu(tr("Mask &tools"));
    for (QAction* a : tools_->actions()) toolsMenu->addAction(a);
    toolsMenu->addSeparator();
    const struct {
        QString name;
        QKeySequence key;
        std::function<void()> run;
    } extras[] = {
        {tr("Smaller brush"), QKeySequence(Qt::Key_BracketLeft), [this] { setBrushRadius(radius_ - kRadiusStep); }},
        {tr("Larger brush"), QKeySequence(Qt::Key_BracketRight), [this] { setBrushRadius(radius_ + kRadiusStep); }},
        {tr("Polygon and fill: swap robot / processed"), QKeySequence(Qt::Key_X), [this] { setAreasAsRobot(!areasAsRobot_); }},
    };
    for (const auto& e : extras) {
        QAction* a = toolsMenu->addAction(e.name);
        a->setShortcut(e.key);
        connect(a, &QAction::triggered, this, e.run);
        editingActions_.push_back(a);
    }
    closeAction_ = toolsMenu->addAction(tr("Close the polygon"));
    closeAction_->setShortcuts({QKeySequence(Qt::Key_Return), QKeySequence(Qt::Key_Enter)});
    connect(closeAction_, &QAction::triggered, this, &MaskEditor::closePolygon);
    editingActions_.push_back(closeAction_);
    for (QAction* a : editingActions_) a->setEnabled(editing_);
}

void MaskEditor::setEditing(bool on)
{
    if (on == editing_) return;
    if (stroking_) onReleased(last_);  // a stroke cut short (Esc, M while dragging) still ends as one step
    editing_ = on;
    polygon_.clear();
    emit editingChanged(on);  // truth marking and the geometry editor give the left button up first
    holdPanes(view_, this, on);
    if (modeAction_) modeAction_->setChecked(on);
    for (QAction* a : editingActions_) a->setEnabled(on);
    toolBar_->setVisible(on);
    for (QWidget* w : previews_) w->setVisible(on);
    emit message(on ? toolHelp() : tr("Mask editing off; File > Save writes the mask beside the config"));
}

QString MaskEditor::toolHelp() const
{
    switch (tool_) {
    case Tool::Brush: return tr("Mask brush: drag to paint robot; [ ] or Ctrl+wheel size; E eraser, P polygon, L fill; M or Esc ends");
    case Tool::Eraser: return tr("Mask eraser: drag to give pixels back to the detector; [ ] or Ctrl+wheel size; M or Esc ends");
    case Tool::Polygon: return tr("Mask polygon: click the vertices, Enter or double-click fills it as %1; Esc drops it")
                            .arg(areasAsRobot_ ? tr("robot") : tr("processed"));
    case Tool::Fill: return tr("Mask fill: click a region to fill it as %1 (X swaps)").arg(areasAsRobot_ ? tr("robot") : tr("processed"));
    }
    return {};
}

void MaskEditor::setTool(Tool tool)
{
    if (tool != Tool::Polygon) polygon_.clear();
    tool_ = tool;
    for (QAction* a : tools_->actions()) a->setChecked(a->data().toInt() == int(tool));
    updatePreviews();
    if (editing_) emit message(toolHelp());
}

void MaskEditor::setBrushRadius(double radius)
{
    radius_ = std::clamp(radius, kMinRadius, kMaxRadius);
    if (radiusBox_->value() != radius_) radiusBox_->setValue(radius_);
    updatePreviews();
}

void MaskEditor::setAreasAsRobot(bool robot)
{
    areasAsRobot_ = robot;
    if (areasBox_->currentIndex() != (robot ? 0 : 1)) areasBox_->setCurrentIndex(robot ? 0 : 1);
    if (editing_) emit message(toolHelp());
}

void MaskEditor::escape()
{
    if (!polygon_.empty()) {
        polygon_.clear();
        updatePreviews();
        emit message(tr("Polygon dropped"));
        return;
    }
    setEditing(false);
}

cv::Mat MaskEditor::maskCopy() const
{
    const Config& c = doc_->config();
    const cv::Size size(c.geometry.imageWidth, c.geometry.imageHeight);
    if (c.mask.empty() || c.mask.size() != size) return cv::Mat(size, CV_8UC1, cv::Scalar(kMaskProcessed));
    return c.mask.clone();
}

Config MaskEditor::withMask(const Config& from, const cv::Mat& mask) const
{
    Config c = from;
    c.mask = mask;
    if (c.geometry.maskFile.empty()) c.geometry.maskFile = kDefaultMaskFile;
    return c;
}

void MaskEditor::commit(const cv::Mat& mask, int changed, const QString& what)
{
    if (changed == 0) {
        emit message(tr("%1: no pixel changed").arg(what));
        return;
    }
    if (const auto why = doc_->replaceConfig(withMask(doc_->config(), mask), what)) {
        emit message(tr("%1 refused: %2").arg(what, *why));
        return;
    }
    emit message(tr("%1: %2 pixel(s) changed (Ctrl+Z undoes)").arg(what).arg(changed));
}

void MaskEditor::onPressed(QPointF p)
{
    switch (tool_) {
    case Tool::Brush:
    case Tool::Eraser:
        stroking_ = true;
        start_ = doc_->config();
        stroke_ = maskCopy();
        last_ = p;
        strokeChanged_ = 0;
        onDragged(p);
        return;
    case Tool::Polygon: {
        const double reach = kCloseDistance / std::max(1e-6, view_->paneScale());
        if (polygon_.size() >= 3 && std::hypot(p.x() - polygon_.front().x(), p.y() - polygon_.front().y()) <= reach) {
            closePolygon();
            return;
        }
        polygon_.push_back(p);
        updatePreviews();
        emit message(tr("Polygon: %1 vertex(es); Enter or double-click fills it, Esc drops it").arg(polygon_.size()));
        return;
    }
    case Tool::Fill: {
        cv::Mat mask = maskCopy();
        const int changed = floodFillMask(mask, toCv(p), areasAsRobot_ ? kMaskRobot : kMaskProcessed);
        commit(mask, changed, areasAsRobot_ ? tr("Fill mask as robot") : tr("Fill mask as processed"));
        return;
    }
    }
}

void MaskEditor::onDragged(QPointF p)
{
    if (!stroking_) return;
    const std::uint8_t value = tool_ == Tool::Brush ? kMaskRobot : kMaskProcessed;
    const int changed = paintStroke(stroke_, toCv(last_), toCv(p), radius_, value);
    last_ = p;
    if (changed == 0) return;
    strokeChanged_ += changed;
    // Live, without an undo step per mouse move; a copy, because the runner reads the last one.
    doc_->applyConfig(withMask(start_, stroke_.clone()));
}

void MaskEditor::onReleased(QPointF p)
{
    if (!stroking_) return;
    onDragged(p);
    stroking_ = false;
    if (strokeChanged_ == 0) return;
    doc_->applyConfig(start_);  // the undo step goes from where the stroke began
    commit(stroke_, strokeChanged_, tool_ == Tool::Brush ? tr("Brush mask") : tr("Erase mask"));
    stroke_ = cv::Mat();
}

bool MaskEditor::closePolygon()
{
    if (polygon_.size() < 3) {
        emit message(tr("A polygon needs at least three vertices"));
        return false;
    }
    std::vector<cv::Point2d> vertices;
    for (const QPointF& v : polygon_) vertices.push_back(toCv(v));
    polygon_.clear();
    updatePreviews();
    cv::Mat mask = maskCopy();
    const int changed = fillPolygon(mask, vertices, areasAsRobot_ ? kMaskRobot : kMaskProcessed);
    commit(mask, changed, areasAsRobot_ ? tr("Polygon as robot") : tr("Polygon as processed"));
    return true;
}

void MaskEditor::updatePreviews()
{
    for (QWidget* w : previews_) w->update();
}

bool MaskEditor::eventFilter(QObject* watched, QEvent* event)
{
    if (!editing_ || !qobject_cast<ImageView*>(watched)) return QObject::eventFilter(watched, event);
    if (event->type() == QEvent::Wheel) {
        auto* wheel = static_cast<QWheelEvent*>(event);
        if (!(wheel->modifiers() & Qt::ControlModifier)) return false;  // plain wheel still zooms
        const int steps = wheel->angleDelta().y() / 120;
        if (steps != 0) setBrushRadius(radius_ + steps * kRadiusStep);
        return true;
    }
    if (event->type() == QEvent::MouseButtonDblClick && tool_ == Tool::Polygon &&
        static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton) {
        closePolygon();  // the double-click's first click already placed the last vertex
        return true;
    }
    return false;
}

}  // namespace omnitune
