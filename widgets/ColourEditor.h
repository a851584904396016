#pragma once
// The Colours panel (issue 10): the colour classes of the segmentation and their HSV boxes,
// edited in the window with every edit one undo step through ConfigDocument (a slider drag is
// one step, the segmented pane follows it live). The class list is the priority order (first
// wins) and shows each class's share of the processed pixels of the frame on screen; below it
// the selected class's name, role, display colour and boxes, the box's H/S/V sliders, the
// sampling tools (ColourSampler), the H-S plane with the boxes on it (ColourPlaneView) and the
// views of the segmented pane: only the selected class, and the pixels two or more classes
// claim striped. "Auto colours" is the automatic first calibration (calib/colour/AutoColour)
// of the frame on screen, as one undo step. The pieces are their own widgets: ColourSamplingBox,
// ColourClassList, ColourBoxEditor, ColourPlaneView and the venue profiles (ColourProfilesBox).
// No vision here: shares, views, sampling and the calibration are calib/colour/ functions.
#include "core/ColourClasses.h"
#include "calib/colour/ClassShares.h"
#include "widgets/PipelineRunner.h"

#include <QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QMenu;
class QPushButton;

namespace omnitune {

class ColourBoxEditor;
class ColourClassList;
class ColourPlaneView;
class ColourProfilesBox;
class ColourSampler;
class ConfigDocument;
class PipelineView;

class ColourEditor : public QWidget {
    Q_OBJECT
public:
    // `doc` and `view` must outlive the editor.
    ColourEditor(ConfigDocument* doc, PipelineView* view, QWidget* parent = nullptr);

    // The run on screen: shares, overlaps, the segmented pane's view; sampling reads its frame.
    void setRun(std::shared_ptr<const PipelineRun> run);
    ColourSampler* sampler() const { return sampler_; }
    // Colours menu: sampling (C, W, [ ]) and Auto colours.
    void fillMenu(QMenu* menu);

    int currentClass() const;
    int currentBox() const;
    void selectClass(int index);
    void selectBox(int index);

    // The edits behind the buttons; each one undo step, or the reason it was refused.
    std::optional<QString> addClass();
    std::optional<QString> removeClass();
    std::optional<QString> moveClass(int delta);  // -1: higher priority
    std::optional<QString> renameClass(const QString& name);
    std::optional<QString> setRole(ColourRole role);
    std::optional<QString> setDisplayColour(const QColor& colour);
    std::optional<QString> setClassEnabled(int index, bool on);
    std::optional<QString> addBox();
    std::optional<QString> removeBox();
    std::optional<QString> autoColours();

    void setOnlyThisClass(bool on);
    void setFlagOverlaps(bool on);
    // The shares of the last run shown (for tests and the list).
    const ClassShares& shares() const { return shares_; }

    QListWidget* classList() const;
    QListWidget* boxList() const { return boxList_; }
    ColourBoxEditor* boxEditor() const { return boxEditor_; }
    ColourPlaneView* planeView() const { return plane_; }
    QLabel* sharesLabel() const { return sharesLabel_; }
    ColourProfilesBox* profiles() const { return profiles_; }

signals:
    void message(const QString& text);  // for the status bar

protected:
    // Shares, histogram and the pane's view are worked out only while the tab is on screen
    // (they cost a pass over the frame per run); hidden, the segmented pane is the plain one.
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void analyse();        // shares and histogram of run_
    std::optional<QString> commit(const Config& next, const QString& text);  // one undo step, or why not
    std::optional<QString> editClass(const QString& text, const std::function<void(ColourClassDef&)>& edit);
    void onBoxEdited(const HsvRange& edited, bool finished);
    void refresh();        // every widget from the document
    void refreshShares();  // the list's shares and the label
    void updateView();     // the segmented pane as asked (only this class, overlaps)
    void syncTarget();     // the sampler samples into the selection
    const ColourClasses& classes() const;

    ConfigDocument* doc_;
    PipelineView* view_;
    ColourSampler* sampler_;
    ColourClassList* classList_;
    QListWidget* boxList_;
    ColourBoxEditor* boxEditor_;
    ColourPlaneView* plane_;
    QLineEdit* name_;
    QComboBox* role_;
    QPushButton* display_;
    QCheckBox* onlyThis_;
    QCheckBox* overlaps_;
    QLabel* sharesLabel_;
    ColourProfilesBox* profiles_;

    std::shared_ptr<const PipelineRun> run_;
    cv::Mat runHsv_;  // run_'s frame in HSV, for the shares
    cv::Mat runUsed_;
    ClassShares shares_;
    bool analysed_ = false;  // shares_ and the histogram are run_'s
    bool refreshing_ = false;
    bool dragging_ = false;  // a box slider is being dragged: the document holds live values
    Config dragStart_;
    int wantClass_ = 0;  // the selection to restore after a refresh
    int wantBox_ = 0;
};

}  // namespace omnitune
