#pragma once
#include <cstdint>

#include "dymesh/core/options.h"
#include "dymesh/core/stiffness.h"

/// NodeForce (spec §3) with saturation, the rebound branch and the unloading state machine (spec §6).
namespace dymesh {

/// Unloading state of a node (spec §6).
enum class UnloadState : std::uint8_t {
  kCannotUnload,       ///< delta_max below UNLOAD_BEGIN: purely plastic, no rebound
  kStartUnload,        ///< delta_max just passed UNLOAD_BEGIN
  kCanUnload,          ///< loaded, at its peak deflection
  kNowUnloading,       ///< on the rebound branch
  kFinishedUnloading,  ///< relaxed to (1-e) delta_max: no force until reloaded
};

/// Loading pressure g(delta) [N/m^2], Eq. 1 and Eq. 2: A below the null band, the cubic in
/// (delta - delta_0) above it, held at its value at SatCrush beyond saturation.
double LoadingPressure(const Stiffness& k, double delta, double null_band);

/// Rebound pressure [N/m^2] (spec §6): zero for delta <= (1-e) delta_max (Eq. 8), else the law of
/// `rebound_law` at delta_r = delta - (1-e) delta_max, capped by the Ku unloading line when Ku > 0.
double ReboundPressure(const Stiffness& k, double delta, double delta_max, double restitution,
                       double null_band, ReboundLaw rebound_law);

/// Next unloading state after a node update (spec §6), given whether the node touches the master.
UnloadState NextUnloadState(UnloadState state, bool touching, double delta, double delta_max,
                            double restitution, const ContactOptions& options);

/// Node pressure [N/m^2] for the state reached: loading law, rebound branch, or zero.
double NodePressure(UnloadState state, bool touching, const Stiffness& k, double delta,
                    double delta_max, double restitution, const ContactOptions& options);

/// Work per unit area [N/m] of the node law when a node's deflection goes from `from` to `to`, given
/// the largest deflection it had reached before (`peak`, DeltaMaxTotal before the update): up to the
/// peak the node travels its rebound curve (unloading gives energy back, reloading takes the same
/// back), past the peak the loading curve (spec §3, §6). Simpson's rule between the laws' kinks
/// (null band, saturation, the zero-force point of Eq. 8): exact for the cubic pieces.
double NodeLawWork(const Stiffness& k, double from, double to, double peak, double restitution,
                   const ContactOptions& options);

}  // namespace dymesh
