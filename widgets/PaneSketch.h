#pragma once
// What an editor draws over an image pane while it works (a brush circle, an open polygon,
// a selected ray): a transparent child of the pane, as large as it, that leaves every mouse
// event to the pane and paints through the editor's function in the pane's coordinates.
#include <QWidget>

#include <functional>

namespace omnitune {

class ImageView;

class PaneSketch : public QWidget {
public:
    using Paint = std::function<void(QPainter&, const ImageView&)>;
    // Hidden until shown; follows the pane's size.
    PaneSketch(ImageView* pane, Paint paint);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;

private:
    ImageView* pane_;
    Paint paint_;
};

}  // namespace omnitune
