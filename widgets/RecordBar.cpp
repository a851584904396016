#include "widgets/RecordBar.h"

#include "calib/camera/CameraRecorder.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace omnitune {

namespace {
QString bytesText(std::uint64_t bytes)
{
    const double gb = double(bytes) / (1024.0 * 1024.0 * 1024.0);
    return gb >= 1.0 ? QStringLiteral("%1 GB").arg(gb, 0, 'f', 1)
                     : QStringLiteral("%1 MB").arg(double(bytes) / (1024.0 * 1024.0), 0, 'f', 0);
}
}  // namespace

RecordBar::RecordBar(QWidget* parent) : QFrame(parent), label_(new QLabel(this)), stop_(new QPushButton(tr("Stop recording"), this))
{
    setObjectName("recordBar");
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet("#recordBar { background: #ffe0e0; } #recordBar QLabel { color: #800000; }");
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(6, 2, 2, 2);
    row->addWidget(label_, 1);
    row->addWidget(stop_);
    stop_->setFocusPolicy(Qt::NoFocus);  // Space stays play / pause
    connect(stop_, &QPushButton::clicked, this, &RecordBar::stopRequested);
    timer_.setInterval(250);
    connect(&timer_, &QTimer::timeout, this, &RecordBar::refresh);
    hide();
}

void RecordBar::setRecorder(CameraRecorder* recorder)
{
    recorder_ = recorder;
    if (!recorder_) {
        timer_.stop();
        hide();
        return;
    }
    elapsed_.start();
    timer_.start();
    refresh();
    show();
}

QString RecordBar::text() const { return label_->text(); }

void RecordBar::refresh()
{
    if (!recorder_) return;
    const CameraRecorderStatus s = recorder_->status();
    const qint64 secs = elapsed_.elapsed() / 1000;
    label_->setText(tr("\u25cf Recording to %1   %2:%3   %4 frames written   %5 dropped   %6 free")
                        .arg(QString::fromStdString(recorder_->folder()))
                        .arg(secs / 60, 2, 10, QLatin1Char('0'))
                        .arg(secs % 60, 2, 10, QLatin1Char('0'))
                        .arg(s.written)
                        .arg(s.dropped)
                        .arg(s.freeBytes > 0 ? bytesText(s.freeBytes) : tr("?")));
    if (!s.running) emit stoppedByItself(QString::fromStdString(s.error.value_or("the recording stopped")));
}

}  // namespace omnitune
