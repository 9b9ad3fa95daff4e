#include "dymesh/io/history_csv.h"

#include <sstream>
#include <string>
#include <vector>

#include "dymesh/analysis/output_units.h"
#include "dymesh/core/units.h"

namespace dymesh {
namespace {

// a CSV field, quoted as RFC 4180 says when it holds a comma, a quote or a line break (a body name may)
std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// the columns of one body, each with its unit in brackets
std::vector<std::string> BodyColumns(const OutputUnits& u) {
  const std::string length = u.length_name, speed = u.speed_name, force = u.force_name, energy = u.energy_name;
  return {"x[" + length + "]", "y[" + length + "]", "yaw[deg]", "vx[" + speed + "]", "vy[" + speed + "]",
          "yaw_rate[deg/s]", "ax_body[g]", "ay_body[g]", "az_body[g]", "fx_body[" + force + "]",
          "fy_body[" + force + "]", "fz_body[" + force + "]", "mz_body[" + std::string(u.moment_name) + "]",
          "crush_energy[" + energy + "]", "friction_energy[" + energy + "]", "kinetic_energy[" + energy + "]",
          "contact_area[" + length + "^2]"};
}

}  // namespace

std::string HistoryCsv(const Simulation& sim) {
  const OutputUnits u = UnitsOf(sim.scenario().units);
  std::ostringstream csv;
  csv.precision(10);
  // header: one column per quantity and body, "BODY.QUANTITY[unit]"
  csv << "time[s]";
  for (int i = 0; i < sim.engine().body_count(); ++i)
    for (const std::string& column : BodyColumns(u)) csv << ',' << CsvField(sim.engine().model(i).name + "." + column);
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
