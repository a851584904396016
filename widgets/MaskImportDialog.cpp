#include "widgets/MaskImportDialog.h"

#include "core/RegularFile.h"
#include "core/RingCoverage.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/MaskEditor.h"
#include "widgets/MaskTint.h"
#include "widgets/Overlay.h"

#include <opencv2/imgcodecs.hpp>

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace omnitune {

namespace {

// The preview's size on screen: the frame scaled to fit this box.
constexpr int kPreviewSide = 420;

}  // namespace

MaskImportDialog::MaskImportDialog(ConfigDocument* doc, const cv::Mat& frame, QWidget* parent)
    : QDialog(parent), doc_(doc), frame_(toQImage(frame)), pathEdit_(new QLineEdit(this)),
      bright_(new QRadioButton(tr("&White (or any bright colour) means process; dark is robot"), this)),
      dark_(new QRadioButton(tr("&Black (dark) means process; bright or coloured is robot"), this)),
      previewLabel_(new QLabel(this)), summary_(new QLabel(this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Import mask"));
    setObjectName(QStringLiteral("maskImport"));
    setMinimumWidth(kPreviewSide + 120);
    auto* layout = new QVBoxLayout(this);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(new QLabel(tr("Mask image:"), this));
    pathEdit_->setObjectName(QStringLiteral("maskPath"));
    pathEdit_->setPlaceholderText(tr("a PNG or BMP of the camera's frame size"));
    connect(pathEdit_, &QLineEdit::editingFinished, this, [this] {
        if (pathEdit_->text() != path_) setFile(pathEdit_->text());
    });
    fileRow->addWidget(pathEdit_, 1);
    auto* choose = new QPushButton(tr("&Choose..."), this);
    connect(choose, &QPushButton::clicked, this, &MaskImportDialog::chooseFile);
    fileRow->addWidget(choose);
    layout->addLayout(fileRow);
    bright_->setChecked(true);
    layout->addWidget(bright_);
    layout->addWidget(dark_);
    connect(bright_, &QRadioButton::toggled, this, [this](bool on) {
        setConvention(on ? MaskConvention::BrightProcesses : MaskConvention::DarkProcesses);
    });
    previewLabel_->setObjectName(QStringLiteral("maskPreview"));
    previewLabel_->setMinimumSize(kPreviewSide, kPreviewSide * 3 / 4);
    previewLabel_->setAlignment(Qt::AlignCenter);
    previewLabel_->setStyleSheet(QStringLiteral("background: #1e1e1e; color: #aaa"));
    layout->addWidget(previewLabel_, 1);
    summary_->setWordWrap(true);
    summary_->setMinimumHeight(summary_->fontMetrics().lineSpacing() * 4 + 4);  // the warning fits unclipped
    summary_->setObjectName(QStringLiteral("maskSummary"));
    layout->addWidget(summary_);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Use this mask"));
    connect(buttons_, &QDialogButtonBox::accepted, this, &MaskImportDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons_);
    update();
}

MaskImportDialog* MaskImportDialog::start(ConfigDocument* doc, const cv::Mat& frame, QWidget* parent)
{
    auto* dialog = new MaskImportDialog(doc, frame, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

void MaskImportDialog::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a mask image"), QFileInfo(path_).path(),
                                                      tr("Images (*.png *.bmp *.pgm *.ppm *.tif *.tiff *.jpg);;All files (*)"));
    if (!path.isEmpty()) setFile(path);
}

void MaskImportDialog::setFile(const QString& path)
{
    path_ = path;
    pathEdit_->setText(path);
    image_.release();
    const std::string file = path.toStdString();
    readProblem_.clear();
    if (path.isEmpty()) {
    } else if (const auto notRegular = checkRegularFile(file)) {
        readProblem_ = tr("%1: %2").arg(path, QString::fromStdString(*notRegular));
    } else {
        try {
            image_ = cv::imread(file, cv::IMREAD_UNCHANGED);
        } catch (const cv::Exception&) {
            image_.release();
        }
        if (image_.empty()) readProblem_ = tr("%1: cannot read it as an image").arg(path);
    }
    update();
}

void MaskImportDialog::setConvention(MaskConvention convention)
{
    convention_ = convention;
    QRadioButton* on = convention == MaskConvention::BrightProcesses ? bright_ : dark_;
    if (!on->isChecked()) on->setChecked(true);  // toggles back into here once
    update();
}

void MaskImportDialog::update()
{
    const GeometryOptions& g = doc_->config().geometry;
    mask_.release();
    problem_ = readProblem_;
    double share = 0.0;
    if (!image_.empty()) {
        const MaskImportResult r = importMask(image_, convention_, g);
        if (r.ok()) {
            mask_ = r.fit.mask;
            share = r.fit.processedShare;
        } else {
            problem_ = tr("%1: %2").arg(path_, QString::fromStdString(r.error->toString()));
        }
    }
    // The frame (or a grey field of the image size) with the robot side tinted and the rings.
    const QSize size(g.imageWidth, g.imageHeight);
    preview_ = frame_.size() == size ? frame_.convertToFormat(QImage::Format_ARGB32_Premultiplied)
                                     : QImage(size, QImage::Format_ARGB32_Premultiplied);
    if (frame_.size() != size) preview_.fill(QColor(70, 70, 70));
    {
        QPainter p(&preview_);
        if (const auto tint = maskTint(mask_)) p.drawImage(0, 0, *tint);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setPen(QPen(overlay_colour::geometry(), 1));
        const QPointF c(g.centerX, g.centerY);
        p.drawEllipse(c, g.innerRadius, g.innerRadius);
        p.drawEllipse(c, g.outerRadius, g.outerRadius);
    }
    if (mask_.empty() && problem_.isEmpty())
        previewLabel_->setText(tr("Choose a mask image: the parts it leaves out will be tinted here"));
    else
        previewLabel_->setPixmap(QPixmap::fromImage(preview_.scaled(kPreviewSide, kPreviewSide, Qt::KeepAspectRatio,
                                                                    Qt::SmoothTransformation)));
    QString text;
    if (!problem_.isEmpty()) {
        text = tr("<b>Not usable:</b> %1").arg(problem_.toHtmlEscaped());
    } else if (!mask_.empty()) {
        text = tr("Tinted: what the detector will not look at. %1 % of the ring between the inner and outer radius "
                  "stays processed.").arg(100.0 * share, 0, 'f', 1);
        if (share < kRingMostlyOffImageShare)
            text += tr(" <b>That leaves most of the field out: if the file means the other side, choose the other "
                       "option above.</b>");
    }
    summary_->setText(text);
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(!mask_.empty());
}

void MaskImportDialog::accept()
{
    if (mask_.empty()) return;
    Config next = doc_->config();
    next.mask = mask_.clone();
    if (next.geometry.maskFile.empty()) next.geometry.maskFile = MaskEditor::kDefaultMaskFile;
    if (const auto why = doc_->replaceConfig(next, tr("Import mask %1").arg(QFileInfo(path_).fileName()))) {
        problem_ = *why;
        summary_->setText(tr("<b>Refused:</b> %1").arg(why->toHtmlEscaped()));
        return;
    }
    QDialog::accept();
}

}  // namespace omnitune
