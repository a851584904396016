#pragma once
// Colour sampling on the image panes (issue 10): in sampling mode (Colours > Sample colours on
// the panes, C) the left button on any pane takes colours from the frame on screen into the
// selected colour class, as SSL-Vision's colour calibration does with its modifiers:
//   drag / click            brush: the pixels under a round brush (radius [ and ]) are added
//   Ctrl + drag / click     brush, removing: the class's boxes are cut so the pixels fall out
//   Shift + drag            rectangle: every pixel of the dragged rectangle is added
//   Ctrl + Shift + drag     rectangle, removing (SSL-Vision's Ctrl+Shift removes too)
//   W                       magic wand instead of the brush: a click takes the region of
//                           similar colour around it (tolerance in the Colours panel)
// The class follows the stroke live on the segmented pane; each stroke is one undo step.
// Pixels outside the processed area (mask, outside the mirror ring) are no samples: the status
// line says how many were ignored. Strokes on several frames add up (step and brush again).
// The algorithms are Qt-free (calib/colour/); this class only turns mouse input into them.
#include "core/Config.h"
#include "calib/colour/BoxFit.h"
#include "calib/colour/MagicWand.h"
#include "widgets/PipelineRunner.h"

#include <QObject>
#include <QPointF>

#include <memory>
#include <vector>

class QAction;
class QMenu;

namespace omnitune {

class ConfigDocument;
class PipelineView;

class ColourSampler : public QObject {
    Q_OBJECT
public:
    enum class Tool { Brush, Wand };
    static constexpr int kMaxBrushRadius = 40;  // image px

    ColourSampler(ConfigDocument* doc, PipelineView* view, QObject* parent = nullptr);

    bool isSampling() const { return sampling_; }
    void setSampling(bool on);
    // The class (list position) and box the samples go to; box -1 (or past the class's boxes)
    // makes a new box from the first stroke.
    void setTarget(int classIndex, int box);
    int targetClass() const { return class_; }
    int targetBox() const { return box_; }
    // The run on screen: strokes sample its frame.
    void setRun(std::shared_ptr<const PipelineRun> run);

    Tool tool() const { return tool_; }
    void setTool(Tool tool);
    int brushRadius() const { return radius_; }
    void setBrushRadius(int px);
    const WandTolerance& wandTolerance() const { return wand_; }
    void setWandTolerance(const WandTolerance& tol) { wand_ = tol; }
    // The box fit of a stroke: outliers from the config (colors.sample_outlier_percent).
    BoxFitOptions fitOptions() const;

    // The gestures, in image px (the panes' signals call these; tests may too).
    void press(QPointF p, Qt::KeyboardModifiers modifiers);
    void drag(QPointF p);
    void release(QPointF p);

    // Colours > sampling mode (C), magic wand (W), brush size ([ and ]).
    void fillMenu(QMenu* menu);
    QAction* samplingAction() const { return samplingAction_; }

signals:
    void samplingChanged(bool on);
    void toolChanged(Tool tool);
    void brushRadiusChanged(int px);
    void message(const QString& text);  // for the status bar
    // A stroke changed the target class (e.g. made its first box): the editor follows.
    void targetEdited(int classIndex, int box);

private:
    // `start_` edited by the stroke so far.
    struct StrokeEdit {
        Config config;
        bool changed = false;
        int box = -1;     // the box that grew
        QString undoText;  // "Add colours to yellow"
        QString summary;   // for the status line
    };
    StrokeEdit edited() const;
    void setMode(bool on);

    ConfigDocument* doc_;
    PipelineView* view_;
    QAction* samplingAction_ = nullptr;
    std::vector<QAction*> sizeActions_;  // [ and ]: enabled while sampling
    QAction* wandAction_ = nullptr;
    bool sampling_ = false;
    int class_ = -1;
    int box_ = -1;
    Tool tool_ = Tool::Brush;
    int radius_ = 3;
    WandTolerance wand_;

    std::shared_ptr<const PipelineRun> run_;

    // The stroke in progress.
    bool active_ = false;
    bool remove_ = false;
    bool rect_ = false;
    bool wandClick_ = false;
    std::vector<cv::Point> path_;
    Config start_;
    std::shared_ptr<const PipelineRun> strokeRun_;  // the frame the stroke samples, whatever arrives meanwhile
    cv::Mat strokeUsed_;
    cv::Mat strokeHsv_;
};

}  // namespace omnitune
