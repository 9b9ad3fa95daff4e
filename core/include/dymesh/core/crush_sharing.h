#pragma once
#include "dymesh/core/stiffness.h"

/// Crush sharing between two deformable bodies (spec §5): how one penetration increment is split so
/// that the forces on the two sides are equal and opposite.
namespace dymesh {

/// Crush-sharing fraction theta (spec §5, Eq. 4-6): the slave's share of the penetration, from the
/// forces each side would carry at the full penetration. A one-shot estimate: exact only when both
/// laws are linear through the origin. `a_master`, `b_master` are the master triangle's corner averages.
double CrushShare(double a_master, double b_master, double a_slave, double b_slave, double delta_total);

/// The slave's share x in [0, depth] of a penetration `depth` [m] that makes the two law pressures
/// equal (spec §5's purpose; SMAC's equal-pressure rule; two crushable layers in series):
///   g_slave(slave_deflection + x) = g_master(master_deflection + depth - x).
/// The pressures are the loading laws of spec §3 (Eq. 1, 2). When one side is already stiffer than
/// the other can become, that side takes none. Where both laws are flat (null band, saturation) every
/// split equalises them, and the one nearest theta (Eq. 7, `theta` * depth) is taken.
double EqualPressureShare(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                          double master_deflection, double depth, double theta, double null_band);

/// theta (Eq. 4-7) for a slave node of law `slave` at `slave_deflection` against a master face of law
/// `master` at `master_deflection` (the face's corner averages), penetration `depth` [m].
double LayerTheta(const Stiffness& slave, double slave_deflection, const Stiffness& master, double master_deflection,
                  double depth);

/// The slave's part of a further closure at the contact, once the penetration `depth` is shared at
/// equal pressure (EqualPressureShare's derivative in depth): two crushable layers in series give way
/// in inverse proportion to their law slopes, k_master / (k_slave + k_master); a side at a flat part of
/// its law (null band, saturation) gives way alone; a side pressing harder than the other's law gives
/// there takes none; where both are flat at one pressure, `theta` splits it.
double SlavePartOfClosure(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                          double master_deflection, double depth, double theta, double null_band);

/// The most a slave node of law `slave` at crush `slave_crush` presses against a master face of law
/// `master` at `master_crush` (the crushes once the penetration is shared; spec §5's purpose, one force
/// through two layers in series): where the slave's law is flat (null band, saturation) and the master
/// gives way below that plateau, the slave holds and carries the master's pressure, not its own;
/// otherwise no bound (infinity: the shared crushes press equally).
double HeldLayerPressure(const Stiffness& slave, double slave_crush, const Stiffness& master, double master_crush,
                         double null_band);

/// A slave node's layer and a master face's layer sharing a penetration (spec §5), solved once:
struct LayerShare {
  double slave_push = 0.0;    ///< [m] the slave's crush increment (EqualPressureShare, theta LayerTheta)
  double slave_part = 0.0;    ///< its part of a further closure (SlavePartOfClosure)
  double max_pressure = 0.0;  ///< [Pa] the most it presses (HeldLayerPressure)
};
LayerShare ShareAtEqualPressure(const Stiffness& slave, double slave_deflection, const Stiffness& master,
                                double master_deflection, double depth, double null_band);

}  // namespace dymesh
