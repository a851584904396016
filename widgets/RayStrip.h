#pragma once
// The colour classes along one radial sensor ray, as a strip under the panes (issue 11): what
// the robot's line and obstacle search reads on that ray, run by run, from its inner to its
// outer radius. It shows one run of the pipeline: the ray's pixels, their classes and the
// runs come from the core's RadialSensors on that run's segmented class image, so the strip
// is what the robot would see with that config. Pixels the geometry or the mask leave out
// are the gaps.
#include "core/ColourClasses.h"
#include "core/RadialSensors.h"

#include <QWidget>

#include <memory>
#include <vector>

namespace omnitune {

struct PipelineRun;

class RayStrip : public QWidget {
    Q_OBJECT
public:
    explicit RayStrip(QWidget* parent = nullptr);

    // Shows `ray` of `run` (a run that was processed); a negative ray or a run that was not
    // processed empties the strip.
    void showRay(const PipelineRun& run, int ray);
    void clear();
    int ray() const { return ray_; }
    const std::vector<ClassRun>& runs() const { return runs_; }

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    int ray_ = -1;
    double angleDeg_ = 0.0;
    RadialSensorOptions options_;
    ColourClasses classes_;  // of the run shown: names and display colours by id
    std::vector<ClassRun> runs_;
};

}  // namespace omnitune
