#include "dymesh/core/node_force.h"

#include <algorithm>
#include <array>

namespace dymesh {
namespace {

// cubic of Eq. 1 in the offset x (= delta - delta_0 on loading, delta_r on rebound)
double Cubic(const Stiffness& k, double x) { return k.A + x * (k.B + x * (k.C + x * k.D)); }

}  // namespace

double LoadingPressure(const Stiffness& k, double delta, double null_band) {
  // spec §3 Eq. 2: beyond SatCrush the force is held at its saturation value
  const double held = k.sat_crush > 0.0 ? std::min(delta, k.sat_crush) : delta;
  // spec §3 Eq. 1: only the constant term acts inside the null band
  if (held <= null_band) return k.A;
  return Cubic(k, held - null_band);
}

double ReboundPressure(const Stiffness& k, double delta, double delta_max, double restitution,
                       double null_band, ReboundLaw rebound_law) {
  // spec §6 Eq. 8: no force once the node relaxed by the restitution fraction of delta_max
  const double delta_r = delta - (1.0 - restitution) * delta_max;
  if (delta_r <= 0.0 || restitution <= 0.0) return 0.0;
  double pressure = 0.0;
  if (rebound_law == ReboundLaw::kScaled) {
    // the loading curve shrunk by e in both axes: returns e^2 of the loading work (restitution e)
    pressure = restitution * LoadingPressure(k, delta_r / restitution, null_band);
  } else {
    // the spec's literal reading: the cubic evaluated at delta_r, saturated like Eq. 2
    const double cap = k.sat_crush > 0.0 ? std::max(k.sat_crush - null_band, 0.0) : delta_r;
    pressure = Cubic(k, std::min(delta_r, cap));
  }
  // the steeper Ku unloading line from the peak bounds the rebound when Ku is given
  if (k.unload_slope > 0.0) {
    const double line = LoadingPressure(k, delta_max, null_band) - k.unload_slope * (delta_max - delta);
    pressure = std::min(pressure, std::max(line, 0.0));
  }
  return pressure;
}

UnloadState NextUnloadState(UnloadState state, bool touching, double delta, double delta_max,
                            double restitution, const ContactOptions& o) {
  const double relaxed = (1.0 - restitution) * delta_max + o.unload_stop;  // UNLOAD_STOP
  const bool at_peak = delta >= delta_max - o.unload_pot;                  // UNLOAD_POT
  switch (state) {
    case UnloadState::kCannotUnload:
      // UNLOAD_BEGIN: enough deflection to have something to give back
      return delta_max >= o.unload_begin ? UnloadState::kStartUnload : state;
    case UnloadState::kStartUnload:
    case UnloadState::kCanUnload:
      if (!touching) return UnloadState::kFinishedUnloading;
      return at_peak ? UnloadState::kCanUnload : UnloadState::kNowUnloading;
    case UnloadState::kNowUnloading:
    case UnloadState::kFinishedUnloading:
      // reloading: on the loading curve again once past the peak, else on the rebound curve
      if (touching && at_peak) return UnloadState::kCanUnload;
      return !touching || delta <= relaxed ? UnloadState::kFinishedUnloading : UnloadState::kNowUnloading;
  }
  return state;
}

double NodePressure(UnloadState state, bool touching, const Stiffness& k, double delta,
                    double delta_max, double restitution, const ContactOptions& o) {
  if (!touching) return 0.0;
  switch (state) {
    case UnloadState::kCannotUnload:
    case UnloadState::kStartUnload:
    case UnloadState::kCanUnload:
      return LoadingPressure(k, delta, o.null_band);
    case UnloadState::kNowUnloading:
      return ReboundPressure(k, delta, delta_max, restitution, o.null_band, o.rebound_law);
    case UnloadState::kFinishedUnloading:
      return 0.0;
  }
  return 0.0;
}

double NodeLawWork(const Stiffness& k, double from, double to, double peak, double restitution,
                   const ContactOptions& o) {
  auto loading = [&](double delta) { return LoadingPressure(k, delta, o.null_band); };
  auto rebound = [&](double delta) {
    return ReboundPressure(k, delta, peak, restitution, o.null_band, o.rebound_law);
  };
  // the kinks of both curves, where Simpson's rule must not straddle
  const double relaxed = (1.0 - restitution) * peak;
  const double scaled_band = relaxed + restitution * o.null_band;  // rebound's null band (scaled law)
  const double kinks[] = {o.null_band, k.sat_crush, relaxed, scaled_band};
  auto integrate = [&](const auto& pressure, double a, double b) {
    if (a == b) return 0.0;
    // signed integral from a to b, split at every kink inside (kept in order by insertion)
    const double lo = std::min(a, b), hi = std::max(a, b);
    std::array<double, 6> cuts{lo};
    int n = 1;
    for (double x : kinks) {
      if (!(x > lo && x < hi)) continue;
      int i = n++;
      for (; i > 1 && cuts[i - 1] > x; --i) cuts[i] = cuts[i - 1];
      cuts[i] = x;
    }
    cuts[n++] = hi;
    double sum = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
      const double x0 = cuts[i], x1 = cuts[i + 1];
      sum += (x1 - x0) / 6.0 * (pressure(x0) + 4.0 * pressure(0.5 * (x0 + x1)) + pressure(x1));
    }
    return b >= a ? sum : -sum;
  };
  // below the peak on the rebound curve, beyond it on the loading curve
  const double below_from = std::min(from, peak), below_to = std::min(to, peak);
  const double above_from = std::max(from, peak), above_to = std::max(to, peak);
  return integrate(rebound, below_from, below_to) + integrate(loading, above_from, above_to);
}

}  // namespace dymesh
