#pragma once
// What each step of the guided set-up (SetupSequence) does in the window: which fit it runs,
// which editor it starts and which panel it shows. Kept here so that the main window only
// hands over its parts.
#include <QWidget>

#include <functional>

namespace omnitune {

class BallModelPanel;
class CameraSetup;
class ColourEditor;
class ConfigDocument;
class DistancePointsPanel;
class GeometryEditor;
class MaskEditor;
class SetupSequence;

struct SetupStepParts {
    ConfigDocument* doc = nullptr;
    CameraSetup* setup = nullptr;
    GeometryEditor* geometry = nullptr;
    MaskEditor* mask = nullptr;
    BallModelPanel* ballModel = nullptr;
    DistancePointsPanel* distances = nullptr;
    ColourEditor* colours = nullptr;
    std::function<void(QWidget*)> showPanel;  // docks (once) and raises a panel
    std::function<bool()> save;               // File > Save config
};

void connectSetupSteps(SetupSequence& sequence, const SetupStepParts& parts);

}  // namespace omnitune
