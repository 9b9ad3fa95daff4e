#include "dymesh/core/crush_sharing.h"

#include <algorithm>
#include <cmath>

#include "dymesh/core/node_force.h"

namespace dymesh {
namespace {

// bisection/Newton iterations of the equal-pressure split; each at least halves the bracket
constexpr int kMaxShareIterations = 60;
// relative bracket width at which the split is converged (round-off of the deflection sums)
constexpr double kShareTolerance = 1e-12;

// relative pressure difference within which the equal-pressure split's two sides agree (its bracket
// closes to 1e-12 of the depth)
constexpr double kSamePressure = 1e-9;

// slope dg/d(delta) of the loading law (spec §3): zero in the null band and beyond saturation
double LoadingSlope(const Stiffness& k, double delta, double null_band) {
  if (delta <= null_band || (k.sat_crush > 0.0 && delta >= k.sat_crush)) return 0.0;
  const double x = delta - null_band;
  return k.B + x * (2.0 * k.C + 3.0 * x * k.D);
}

// the slave's part of a further closure with the layers at crushes c_slave and c_master (shared)
double SlavePartAtCrushes(const Stiffness& slave, double c_slave, const Stiffness& master, double c_master,
                          double theta, double null_band) {
  // two hardening layers give way in inverse proportion to their slopes
  const double k_slave = LoadingSlope(slave, c_slave, null_band);
  const double k_master = LoadingSlope(master, c_master, null_band);
  if (k_slave > 0.0 && k_master > 0.0) return k_master / (k_slave + k_master);
  // a flat layer (null band, saturation) gives way alone once the other presses as hard as it holds;
  // pressed less, it holds and the other gives way; both flat at one pressure: theta
  const double p_slave = LoadingPressure(slave, c_slave, null_band);
  const double p_master = LoadingPressure(master, c_master, null_band);
  const double tolerance = kSamePressure * std::max(std::abs(p_slave), std::abs(p_master));
  const bool slave_gives = k_slave <= 0.0 && p_slave <= p_master + tolerance;
  const bool master_gives = k_master <= 0.0 && p_master <= p_slave + tolerance;
  if (slave_gives && master_gives) return std::clamp(theta, 0.0, 1.0);
  if (slave_gives) return 1.0;
  if (master_gives) return 0.0;
  return k_slave <= 0.0 ? 0.0 : 1.0;  // the flat one holds: the hardening one gives way
}

// one equal-pressure solve with the first estimate `theta`; the part of a further closure and the
// pressure bound at the crushes it leaves
LayerShare ShareWithTheta(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                          double master_deflection, double depth, double theta, double null_band) {
  LayerShare out;
  out.slave_push = EqualPressureShare(slave, slave_deflection, master, master_deflection, depth, theta, null_band);
  const double c_slave = slave_deflection + out.slave_push;
  const double c_master = master_deflection + std::max(depth, 0.0) - out.slave_push;
  out.slave_part = SlavePartAtCrushes(slave, c_slave, master, c_master, theta, null_band);
  out.max_pressure = HeldLayerPressure(slave, c_slave, master, c_master, null_band);
  return out;
}

}  // namespace

double CrushShare(double a_master, double b_master, double a_slave, double b_slave, double delta_total) {
  // spec §5 Eq. 4-6: theta = F_master / (F_master + F_slave) at the full penetration
  const double f_master = a_master + b_master * delta_total;
  const double f_slave = a_slave + b_slave * delta_total;
  const double sum = f_master + f_slave;
  return sum > 0.0 ? f_master / sum : 0.5;
}

double EqualPressureShare(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                          double master_deflection, double depth, double theta, double null_band) {
  if (!(depth > 0.0)) return 0.0;
  // pressure mismatch h(x) = g_slave - g_master; it never decreases in x (both laws non-decreasing)
  auto mismatch = [&](double x) {
    return LoadingPressure(slave, slave_deflection + x, null_band) -
           LoadingPressure(master, master_deflection + depth - x, null_band);
  };
  auto slope = [&](double x) {
    return LoadingSlope(slave, slave_deflection + x, null_band) +
           LoadingSlope(master, master_deflection + depth - x, null_band);
  };
  // one side already at least as stiff as the other can become: the other takes it all
  const double at_zero = mismatch(0.0), at_full = mismatch(depth);
  if (at_zero >= 0.0 && at_full > 0.0) return 0.0;
  if (at_full <= 0.0 && at_zero < 0.0) return depth;
  // theta's split is the first estimate; bracket the root on its side
  double x = std::clamp(theta, 0.0, 1.0) * depth;
  double h = mismatch(x);
  if (h == 0.0) return x;  // flat laws (null band, saturation): every split is equal, keep theta's
  double lo = h < 0.0 ? x : 0.0, hi = h < 0.0 ? depth : x;
  for (int i = 0; i < kMaxShareIterations && hi - lo > kShareTolerance * depth; ++i) {
    // Newton step inside the bracket (one step for linear laws), bisection when it would leave it
    const double s = slope(x);
    double next = s > 0.0 ? x - h / s : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = next;
    h = mismatch(x);
    if (h == 0.0) return x;
    (h < 0.0 ? lo : hi) = x;
  }
  return x;
}

double LayerTheta(const Stiffness& slave, double slave_deflection, const Stiffness& master, double master_deflection,
                  double depth) {
  return CrushShare(master.A + master.B * master_deflection, master.B, slave.A + slave.B * slave_deflection, slave.B,
                    depth);
}

double SlavePartOfClosure(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                          double master_deflection, double depth, double theta, double null_band) {
  return ShareWithTheta(slave, slave_deflection, master, master_deflection, depth, theta, null_band).slave_part;
}

double HeldLayerPressure(const Stiffness& slave, double slave_crush, const Stiffness& master, double master_crush,
                         double null_band) {
  // a layer at a flat part of its law holds (takes no crush) while the other presses less than that
  // plateau, and passes the other's pressure on; a hardening layer carries its own (the share equalised it)
  if (LoadingSlope(slave, slave_crush, null_band) > 0.0) return INFINITY;
  return LoadingPressure(master, master_crush, null_band);
}

LayerShare ShareAtEqualPressure(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                                double master_deflection, double depth, double null_band) {
  const double theta = LayerTheta(slave, slave_deflection, master, master_deflection, depth);
  return ShareWithTheta(slave, slave_deflection, master, master_deflection, depth, theta, null_band);
}

}  // namespace dymesh
