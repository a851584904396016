#include "widgets/ColourDiffView.h"

#include "calib/colour/ColourProfileDiff.h"
#include "core/Geometry.h"
#include "widgets/ImageView.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr int kPictureSide = 480;  // px on screen; the frame scales to fit

}  // namespace

ColourDiffView::ColourDiffView(const QString& leftName, const ColorLutOptions& left, const QString& rightName,
                               const ColorLutOptions& right, const Frame& frame, QWidget* parent)
    : QDialog(parent), table_(new QTableWidget), picture_(new QLabel), summary_(new QLabel)
{
    setWindowTitle(tr("Compare colours: %1 and %2").arg(leftName, rightName));
    setObjectName("colourDiffView");
    auto* layout = new QVBoxLayout(this);

    const std::vector<ColourDiffRow> rows = diffColourCalibrations(left, right);
    table_->setObjectName("diffTable");
    table_->setColumnCount(3);
    table_->setHorizontalHeaderLabels({tr("Setting / class"), leftName, rightName});
    table_->setRowCount(int(rows.size()));
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    const QColor changedRow(255, 225, 150);  // amber: readable with black text
    int differing = 0;
    for (int r = 0; r < int(rows.size()); ++r) {
        const ColourDiffRow& row = rows[std::size_t(r)];
        int c = 0;
        for (const std::string& text : {row.what, row.left, row.right}) {
            auto* item = new QTableWidgetItem(QString::fromStdString(text));
            if (!row.same) {
                item->setBackground(changedRow);
                QFont f = item->font();
                f.setBold(c == 0);
                item->setFont(f);
            }
            table_->setItem(r, c++, item);
        }
        differing += row.same ? 0 : 1;
    }
    table_->resizeColumnsToContents();
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
    layout->addWidget(new QLabel(differing == 0 ? tr("The two calibrations are the same.")
                                                : tr("%n row(s) differ (highlighted).", nullptr, differing)));
    layout->addWidget(table_, 1);

    picture_->setObjectName("diffPicture");
    picture_->setAlignment(Qt::AlignCenter);
    summary_->setObjectName("diffSummary");
    summary_->setWordWrap(true);
    const cv::Size size(frame.config.geometry.imageWidth, frame.config.geometry.imageHeight);
    if (!frame.raw.empty() && frame.raw.size() == size && frame.acquired.size() == size && frame.acquired.type() == CV_8UC3) {
        const ClassChanges changes =
            classChanges(frame.raw, frame.format, Geometry(frame.config.geometry, frame.config.mask), left, right);
        changed_ = changes.changed;
        // A changed pixel stays visible when the frame is shown smaller: marks of about one screen px.
        const double shrink = double(std::max(size.width, size.height)) / kPictureSide;
        const int mark = shrink > 1.2 ? int(std::ceil(shrink / 2.0)) : 0;
        const QImage image = toQImage(classChangeImage(frame.acquired, changes.mask, 0.35, mark));
        picture_->setPixmap(QPixmap::fromImage(image.scaled(kPictureSide, kPictureSide, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
        summary_->setText(tr("Frame %1, dimmed: the pixels in magenta change class, %2 % of the processed pixels (%3 px).")
                              .arg(frame.index)
                              .arg(100.0 * changes.share(), 0, 'f', changes.share() > 0 && changes.share() < 0.01 ? 2 : 1)
                              .arg(changes.changed));
        layout->addWidget(picture_);
    } else {
        summary_->setText(tr("No processed frame on screen: open one to see the pixels that change class."));
    }
    layout->addWidget(summary_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(960, 820);
}

}  // namespace omnitune
