#pragma once
// Expected ball radius in the image as a function of the distance to the robot centre
// (thesis Fig. 4.7: a 2nd-order polynomial fitted to measurements), and the side of the
// square that holds the ball (`ballSquareSize`).

namespace omnitune {

struct BallModelOptions {
    // radius(d) = c0 + c1*d + c2*d^2, d and radius in px. Refit per robot and camera.
    double c0 = 39.0;       // px
    double c1 = -0.28333;   // px/px
    double c2 = 0.00055556; // px/px^2
    double minRadius = 3.0;  // px; the model is clamped to [minRadius, maxRadius]
    double maxRadius = 25.0; // px; the ball engaged in the robot
    // Side of the validation square over the ball diameter. Below ~0.7 the square sees only the
    // ball's middle; above 1 it takes in the carpet around it and the non-green test fails.
    double squareRatio = 0.75;
    // Per-direction correction for an off-axis mirror, where the ball looks bigger on one side:
    // r(d, a) = r(d) * (1 + directionCos*cos(a) + directionSin*sin(a)), a the image angle of the
    // ball's offset from the mirror centre (atan2(dy, dx), image x right, y down). 0 and 0: none.
    double directionCos = 0.0;  // ratio
    double directionSin = 0.0;  // ratio
    // Radial squash of the ball's image: its radial over its tangential semi-axis, k(d) = squashC0
    // + squashC1*d + squashC2*d^2 (d in px). A mirror that compresses the far field radially (a
    // spherical one) shows the ball as an ellipse; r(d) is then its area-equivalent radius
    // sqrt(radial * tangential). 1, 0, 0: a circle (the thesis).
    double squashC0 = 1.0;  // ratio
    double squashC1 = 0.0;  // 1/px
    double squashC2 = 0.0;  // 1/px^2
};

class BallModel {
public:
    BallModel() = default;
    explicit BallModel(const BallModelOptions& options) : options_(options) {}

    double radiusAt(double distancePx) const;
    // With the per-direction correction; exactly radiusAt(distancePx) when it is 0 and 0.
    double radiusAt(double distancePx, double angleRad) const;
    // Odd side length (px) of the square that holds a ball at this distance (and direction).
    int squareSizeAt(double distancePx) const;
    int squareSizeAt(double distancePx, double angleRad) const;
    // Radial over tangential semi-axis at this distance; 1 where the model gives no positive ratio.
    double squashAt(double distancePx) const;
    const BallModelOptions& options() const { return options_; }

private:
    BallModelOptions options_;
};

}  // namespace omnitune
