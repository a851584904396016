#pragma once
// File > Import mask... (issue 11): a mask image made elsewhere, previewed before it replaces
// the config's. The user chooses the file and which side means "process" (white or any bright
// colour, or black); the preview tints what would NOT be processed over the frame on screen
// with the robot's rings, and says how much of the ring stays processed, so a mask of the
// opposite convention shows at once as a tinted field. calib/mask/MaskImport does the
// conversion and refuses another size or an image of one value; OK stays off until it passes.
// Accepting replaces the mask as one undo step.
#include "calib/mask/MaskImport.h"
#include "core/Config.h"

#include <QDialog>
#include <QImage>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QRadioButton;

namespace omnitune {

class ConfigDocument;

class MaskImportDialog : public QDialog {
    Q_OBJECT
public:
    // `frame`: the frame on screen (BGR or grey), the preview's background; may be empty.
    MaskImportDialog(ConfigDocument* doc, const cv::Mat& frame, QWidget* parent = nullptr);

    // Opens a dialog window-modally (without blocking) that deletes itself when closed.
    static MaskImportDialog* start(ConfigDocument* doc, const cv::Mat& frame, QWidget* parent);

    void setFile(const QString& path);
    void setConvention(MaskConvention convention);
    MaskConvention convention() const { return convention_; }
    // The converted mask (CV_8UC1, 255 = process); empty while the file is refused or missing.
    const cv::Mat& mask() const { return mask_; }
    QString problem() const { return problem_; }  // why OK is off; empty when it is on
    // The preview at image resolution: frame, tint of the robot side, rings.
    const QImage& preview() const { return preview_; }
    QDialogButtonBox* buttons() const { return buttons_; }

    void accept() override;

private:
    void chooseFile();
    void update();  // converts the file with the chosen convention and redraws the preview

    ConfigDocument* doc_;
    QImage frame_;
    cv::Mat image_;  // the file as read
    cv::Mat mask_;
    MaskConvention convention_ = MaskConvention::BrightProcesses;
    QString path_;
    QString readProblem_;  // the file could not be read
    QString problem_;      // that, or why the conversion refused it
    QImage preview_;

    QLineEdit* pathEdit_;
    QRadioButton* bright_;
    QRadioButton* dark_;
    QLabel* previewLabel_;
    QLabel* summary_;
    QDialogButtonBox* buttons_;
};

}  // namespace omnitune
