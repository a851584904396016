#pragma once
// A PI controller in velocity form: each update returns the change of the output,
//     du = kp * (e_k - e_{k-1}) + ki * e_k,
// so the output is the camera's register itself and a feature clamped at its limit does not
// wind an integral up.
namespace omnitune {

class PiController {
public:
    PiController(double kp = 0.0, double ki = 0.0) : kp_(kp), ki_(ki) {}

    double update(double error)
    {
        const double du = kp_ * (error - (started_ ? last_ : error)) + ki_ * error;
        last_ = error;
        started_ = true;
        return du;
    }
    void reset() { started_ = false; }

private:
    double kp_ = 0.0, ki_ = 0.0;
    double last_ = 0.0;
    bool started_ = false;
};

}  // namespace omnitune
