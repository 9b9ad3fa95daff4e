#include "dymesh/core/contact_stick.h"

namespace dymesh {

Vec3 StickingCorrection(const Vec3& slide_step, double push, double depth, double mu) {
  if (!(mu > 0.0) || !(push > 0.0) || !(depth > 0.0)) return Vec3::Zero();
  // return mapping onto the friction cone: the trial correction undoes the node's share of the slip,
  // and is scaled back to the cone's radius mu * push when friction cannot hold that much
  const Vec3 trial = -(push / depth) * slide_step;
  const double radius = mu * push;
  const double length = trial.norm();
  return length > radius ? Vec3((radius / length) * trial) : trial;
}

}  // namespace dymesh
