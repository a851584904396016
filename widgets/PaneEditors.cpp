#include "widgets/PaneEditors.h"

#include "widgets/DistancePointsPanel.h"
#include "widgets/GeometryEditor.h"
#include "widgets/MaskEditor.h"
#include "widgets/MaskImportDialog.h"
#include "widgets/PipelineRunner.h"
#include "widgets/RadialSensorEditor.h"
#include "widgets/ReferenceRegionEditor.h"
#include "widgets/TruthMarker.h"

#include <QAction>
#include <QMenu>

namespace omnitune {

PaneEditors::PaneEditors(ConfigDocument* doc, PipelineView* view, GeometryEditor* geometry, TruthMarker* marker,
                         RayStrip* strip, QWidget* parent)
    : QObject(parent), doc_(doc), parent_(parent), geometry_(geometry), marker_(marker),
      mask_(new MaskEditor(doc, view, this)), sensors_(new RadialSensorEditor(doc, view, strip, this)),
      distances_(new DistancePointsPanel(doc, view, parent)), references_(new ReferenceRegionEditor(doc, view, this))
{
    connect(references_, &ReferenceRegionEditor::message, this, &PaneEditors::message);
    connect(references_, &ReferenceRegionEditor::editingChanged, this, [this](bool on) { exclusive(references_, on); });
    connect(distances_, &DistancePointsPanel::message, this, &PaneEditors::message);
    connect(distances_, &DistancePointsPanel::addingChanged, this, [this](bool on) { exclusive(distances_, on); });
    connect(mask_, &MaskEditor::message, this, &PaneEditors::message);
    connect(sensors_, &RadialSensorEditor::message, this, &PaneEditors::message);
    connect(mask_, &MaskEditor::editingChanged, this, [this](bool on) { exclusive(mask_, on); });
    connect(sensors_, &RadialSensorEditor::editingChanged, this, [this](bool on) { exclusive(sensors_, on); });
    connect(geometry_, &GeometryEditor::editingChanged, this, [this](bool on) { exclusive(geometry_, on); });
    connect(marker_, &TruthMarker::markingChanged, this, [this](bool on) { exclusive(marker_, on); });
}

void PaneEditors::exclusive(const QObject* from, bool on)
{
    if (!on) return;
    releaseAllBut(from);
    emit leftButtonTaken();
}

void PaneEditors::releaseLeftButton() { releaseAllBut(nullptr); }

void PaneEditors::releaseAllBut(const QObject* keep)
{
    if (keep != mask_) mask_->setEditing(false);
    if (keep != sensors_) sensors_->setEditing(false);
    if (keep != distances_) distances_->setAdding(false);
    if (keep != references_) references_->setEditing(false);
    if (keep != geometry_) geometry_->setEditing(false);
    if (keep != marker_ && marker_->isMarking()) marker_->setMarking(false);
}

void PaneEditors::fillMenu(QMenu* camera)
{
    mask_->fillMenu(camera);
    QAction* import = camera->addAction(tr("&Import mask..."), this, [this] {
        MaskImportDialog::start(doc_, run_ ? run_->result.stages.acquired : cv::Mat(), parent_);
    });
    import->setObjectName(QStringLiteral("importMask"));
    import->setStatusTip(tr("Use a mask image made elsewhere, after a preview; choose which side means process"));
    camera->addSeparator();
    sensors_->fillMenu(camera);
    references_->fillMenu(camera);
}

void PaneEditors::setRun(std::shared_ptr<const PipelineRun> run)
{
    run_ = run;
    sensors_->setRun(std::move(run));
}

void PaneEditors::stopEditing()
{
    mask_->setEditing(false);
    sensors_->setEditing(false);
    distances_->setAdding(false);
    references_->setEditing(false);
    run_.reset();
    sensors_->setRun(nullptr);
}

void PaneEditors::escape()
{
    if (mask_->isEditing()) {
        mask_->escape();
        return;
    }
    sensors_->setEditing(false);
    distances_->setAdding(false);
    references_->setEditing(false);
}

}  // namespace omnitune
