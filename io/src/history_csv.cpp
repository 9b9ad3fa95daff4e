#include "dymesh/io/history_csv.h"

#include <sstream>

#include "dymesh/analysis/output_units.h"
#include "dymesh/core/units.h"

namespace dymesh {

std::string HistoryCsv(const Simulation& sim) {
  const OutputUnits u = UnitsOf(sim.scenario().units);
  std::ostringstream csv;
  csv.precision(10);
  // header: one column per quantity, unit in brackets
  csv << "time[s]";
  for (int i = 0; i < sim.engine().body_count(); ++i) {
    const std::string n = sim.engine().model(i).name + ".";
    csv << ',' << n << "x[" << u.length_name << "]," << n << "y[" << u.length_name << "]," << n << "yaw[deg],"
        << n << "vx[" << u.speed_name << "]," << n << "vy[" << u.speed_name << "]," << n << "yaw_rate[deg/s],"
        << n << "ax_body[g]," << n << "ay_body[g]," << n << "az_body[g],"
        << n << "fx_body[" << u.force_name << "]," << n << "fy_body[" << u.force_name << "]," << n << "fz_body["
        << u.force_name << "]," << n << "mz_body[" << u.moment_name << "]," << n << "crush_energy["
        << u.energy_name << "]," << n << "friction_energy[" << u.energy_name << "]," << n << "kinetic_energy["
        << u.energy_name << "]," << n << "contact_area[" << u.length_name << "^2]";
  }
  csv << '\n';
  const double g = units::kStandardGravity;
  for (const Sample& s : sim.history()) {
    csv << s.time;
    for (int i = 0; i < sim.engine().body_count(); ++i) {
      const BodySample& b = s.bodies[i];
      csv << ',' << b.rigid.position.x() * u.length << ',' << b.rigid.position.y() * u.length << ','
          << b.rigid.yaw * kRadToDeg << ',' << b.rigid.velocity.x() * u.speed << ','
          << b.rigid.velocity.y() * u.speed << ',' << b.rigid.omega.z() * kRadToDeg << ','
          << b.accel_body.x() / g << ',' << b.accel_body.y() / g << ',' << b.accel_body.z() / g << ','
          << b.loads.force_body.x() * u.force << ',' << b.loads.force_body.y() * u.force << ','
          << b.loads.force_body.z() * u.force << ',' << b.loads.moment_body.z() * u.moment << ','
          << b.crush_energy * u.energy << ',' << b.friction_energy * u.energy << ','
          << KineticEnergy(sim.engine().model(i), b.rigid) * u.energy << ','
          << b.contact_area * u.length * u.length;
    }
    csv << '\n';
  }
  return csv.str();
}


}  // namespace dymesh
