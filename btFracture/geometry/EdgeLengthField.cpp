#include <btFracture/geometry/EdgeLengthField.h>

#include <algorithm>

namespace btfracture {

double EdgeLengthField::at(const Eigen::Vector3d& p) const {
    double factor = 1.0;
    for (const Ball& ball : balls_)
        if ((p - ball.centre).squaredNorm() <= ball.radius2) factor = std::min(factor, ball.factor);
    return base_ * factor;
}

void EdgeLengthField::refine(const Eigen::Vector3d& centre, double radius, double factor) {
    balls_.push_back({centre, radius * radius, at(centre) / base_ * factor});
}

}  // namespace btfracture
