#pragma once
// What the panes draw over the images, and which of it is switched on.
#include "core/BallCandidate.h"
#include "core/Config.h"
#include "calib/mask/MaskOutline.h"
#include "core/PipelineResult.h"

#include <QColor>
#include <QImage>

#include <memory>
#include <vector>

namespace omnitune {

// The overlay's colours, shared by the panes and the legend that explains them.
namespace overlay_colour {
inline QColor geometry() { return QColor(255, 255, 0, 200); }      // robot centre, inner and outer radius
inline QColor maskOutline() { return QColor(255, 160, 0, 220); }
inline QColor maskTint() { return QColor(255, 120, 0, 80); }      // pixels the mask leaves out
inline QColor areas() { return QColor(0, 200, 255, 160); }        // radial area bounds, dashed
inline QColor sensors() { return QColor(255, 255, 255, 90); }
inline QColor accepted() { return QColor(0, 255, 0); }             // accepted candidate and ball
inline QColor rejected() { return QColor(255, 90, 60); }
inline QColor truth() { return QColor(255, 60, 255); }             // ground truth, dashed
inline QColor cursor() { return QColor(255, 255, 255, 200); }      // expected ball under the cursor, dotted
}  // namespace overlay_colour

struct OverlayOptions {
    bool geometry = true;      // robot centre, inner and outer radius, mask outline
    bool areas = true;         // the radial areas of the specific Hough
    bool sensors = false;      // radial sensor rays
    bool candidates = true;    // every candidate with its three scores
    bool ball = true;          // the accepted ball with its world position
    bool cursorRadius = true;  // the expected ball circle under the cursor
    bool truth = true;         // the ground truth marked for this frame
};

// The ground truth of the frame on screen, as the panes draw it.
struct TruthOverlay {
    enum State { Unmarked, NoBall, Ball };
    State state = Unmarked;
    double x = 0.0, y = 0.0, radius = 0.0;  // image px, when state == Ball
    bool marking = false;  // truth-marking mode: say "not marked" instead of drawing nothing
};

struct OverlayData {
    Config config;                        // geometry, areas, ball model, sensors of the run
    std::shared_ptr<const Polylines> maskOutline;  // border of config.mask; null or empty: none
    std::shared_ptr<const QImage> maskTint;        // config.mask's unprocessed pixels, tinted; null: none
    std::vector<BallCandidate> candidates;
    BallDetection detection;
};

}  // namespace omnitune
