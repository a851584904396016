#pragma once
// Green panels of a ball (issue 9): a ball whose panels have the carpet's own hue and saturation
// is still a ball. Colour cannot tell such a panel from the carpet; its place can. A panel inside
// the ball is enclosed by the ball's other panels: walking out from it, away from the ball's
// centre, the ball's white comes before the ball's border. Carpet seen inside the circle of a
// false candidate opens onto the carpet outside it.
#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace omnitune {

// The ball's disc: the candidate's expected circle, in image px.
struct BallDisc {
    double x = 0;
    double y = 0;
    double radius = 0;
};

// What the walk needs to know of a pixel.
class PanelPixels {
public:
    virtual ~PanelPixels() = default;
    // Inside the image and processed.
    virtual bool known(cv::Point p) const = 0;
    // Of a field class (carpet, or a green panel): the walk goes on through it.
    virtual bool field(cv::Point p) const = 0;
};

// Whether the green pixel `p` lies on an enclosed panel of the ball in `disc`: walking out from p
// (away from the disc's centre, 0.5 px steps) to `marginPx` inside the border, it meets a known
// pixel of no field class. A walk that leaves the known pixels first says nothing (false): a
// ball half behind a rod keeps only its visibly enclosed panels.
bool onEnclosedPanel(cv::Point p, const BallDisc& disc, double marginPx, const PanelPixels& pixels);

// Whether in at least `minDirections` of the 8 compass directions walking from the green pixel `p`
// meets a known pixel of no field class before leaving the disc (less `marginPx`). A green panel
// at the ball's silhouette has the ball's white inwards and on both sides (5 of 8), carpet beside
// a line or in a line corner has it on one or two sides (3-5 of 8, at a corner). Walks only until
// the answer is known.
bool enclosedFrom(cv::Point p, const BallDisc& disc, double marginPx, int minDirections, const PanelPixels& pixels);

// onEnclosedPanel (or at least minDirections enclosing directions, 0: not asked) for one candidate, memoised per pixel of the disc's bounding box: the colour
// tests ask about the same pixels many times (every ray step, the square). Reset per candidate;
// the memo's storage is kept, so a warm pipeline allocates nothing.
class EnclosedPanels {
public:
    // `pixels` must outlive the calls to at() until the next reset.
    void reset(const BallDisc& disc, double marginPx, int minDirections, const PanelPixels& pixels);
    bool at(cv::Point p) const;

private:
    BallDisc disc_;
    double margin_ = 0;
    int minDirections_ = 0;
    const PanelPixels* pixels_ = nullptr;
    int x0_ = 0;
    int y0_ = 0;
    int side_ = 0;
    mutable std::vector<std::int8_t> memo_;  // -1 not yet asked, 0 no, 1 yes
};

}  // namespace omnitune
