#include "widgets/SetupSteps.h"

#include "widgets/BallModelPanel.h"
#include "widgets/CameraSetup.h"
#include "widgets/ColourEditor.h"
#include "widgets/ConfigDocument.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/GeometryEditor.h"
#include "widgets/MaskEditor.h"
#include "widgets/SetupSequence.h"

#include <QFileInfo>

namespace omnitune {

void connectSetupSteps(SetupSequence& sequence, const SetupStepParts& parts)
{
    using Step = SetupSequence::Step;
    const SetupStepParts p = parts;
    // The circles stay draggable and the arrows nudge the centre while the geometry is set.
    const auto editGeometry = [p] {
        p.mask->setEditing(false);
        p.geometry->setEditing(true);
    };
    const auto editNothing = [p] {
        p.geometry->setEditing(false);
        p.mask->setEditing(false);
    };
    sequence.setActions(Step::CentreRim, {editGeometry, [p] { return p.setup->fitCentreAndRim(); }});
    sequence.setActions(Step::Body, {editGeometry, [p] { return p.setup->fitRobotBody(); }});
    sequence.setActions(Step::Mask, {editNothing, [p] {
                                         SetupStepOutcome out = p.setup->proposeMask();
                                         if (out.ok) p.mask->setEditing(true);  // brush and eraser correct it
                                         return out;
                                     }});
    sequence.setActions(Step::BallModel, {[p, editNothing] {
                                              editNothing();
                                              p.showPanel(p.ballModel);
                                          },
                                          [p] { return p.ballModel->apply(); }});
    sequence.setActions(Step::DistanceMap, {[p, editNothing] {
                                                editNothing();
                                                p.showPanel(p.distances);
                                            },
                                            [p] { return SetupStepOutcome{p.distances->fit(), p.distances->status()}; }});
    sequence.setActions(Step::Colours, {[p] { p.showPanel(p.colours); },
                                        [p] {
                                            if (const auto why = p.colours->autoColours()) return SetupStepOutcome{false, *why};
                                            return SetupStepOutcome{true, QObject::tr("first colours from the frame on screen")};
                                        }});
    sequence.setActions(Step::Save, {editNothing, [p] {
                                         if (!p.save()) return SetupStepOutcome{false, QObject::tr("the config was not saved")};
                                         return SetupStepOutcome{true, QObject::tr("saved as %1").arg(p.doc->path())};
                                     }});
}

}  // namespace omnitune
