#include "widgets/MaskTint.h"

#include "widgets/Overlay.h"

namespace omnitune {

std::shared_ptr<const QImage> maskTint(const cv::Mat& mask)
{
    if (mask.empty() || mask.type() != CV_8UC1) return nullptr;
    QImage tint(mask.cols, mask.rows, QImage::Format_ARGB32_Premultiplied);
    const QColor c = overlay_colour::maskTint();
    const double a = c.alphaF();
    const QRgb on = qRgba(int(c.red() * a), int(c.green() * a), int(c.blue() * a), c.alpha());  // premultiplied
    for (int y = 0; y < mask.rows; ++y) {
        const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
        auto* row = reinterpret_cast<QRgb*>(tint.scanLine(y));
        for (int x = 0; x < mask.cols; ++x) row[x] = m[x] ? 0u : on;
    }
    return std::make_shared<const QImage>(std::move(tint));
}

}  // namespace omnitune
