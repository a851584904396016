#pragma once
// Two colour calibrations compared (a venue profile against the config, or two profiles): the
// settings and classes side by side with the rows that differ highlighted, and the frame on
// screen dimmed with the pixels that change class from one to the other in magenta, with their
// share of the processed pixels. The comparison itself is calib/colour/ColourProfileDiff.
#include "core/ColorLut.h"
#include "core/Config.h"
#include "core/PixelFormat.h"

#include <QDialog>

#include <opencv2/core.hpp>

class QLabel;
class QTableWidget;

namespace omnitune {

class ColourDiffView : public QDialog {
    Q_OBJECT
public:
    // The frame to show the changes on: BGR `acquired` of `config`'s geometry (empty: no frame,
    // the table alone).
    struct Frame {
        cv::Mat raw;  // as the detector segments it
        PixelFormat format = PixelFormat::Bgr8;
        cv::Mat acquired;  // BGR, for the picture
        Config config;     // geometry and mask of the frame
        int index = -1;
    };
    ColourDiffView(const QString& leftName, const ColorLutOptions& left, const QString& rightName,
                   const ColorLutOptions& right, const Frame& frame, QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }
    QLabel* picture() const { return picture_; }
    QLabel* summary() const { return summary_; }
    int changedPixels() const { return changed_; }

private:
    QTableWidget* table_;
    QLabel* picture_;
    QLabel* summary_;
    int changed_ = -1;  // -1: no frame compared
};

}  // namespace omnitune
