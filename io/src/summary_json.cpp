#include "dymesh/io/summary_json.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "dymesh/core/units.h"

namespace dymesh {
namespace {

nlohmann::json Vector(const Vec3& v, double scale) { return {v.x() * scale, v.y() * scale, v.z() * scale}; }

// C1..C6 with the damage width and stations, in output lengths
nlohmann::json CrushProfileJson(const CrushProfile& p, double length) {
  nlohmann::json stations = nlohmann::json::array(), crush = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    stations.push_back(p.station[i] * length);
    crush.push_back(p.crush[i] * length);
  }
  return {{"face", CrushFaceName(p.face)}, {"width", p.width * length}, {"centre", p.centre * length},
          {"stations", stations}, {"c", crush}, {"max_depth", p.max_depth * length}};
}


// a failed run's overflowed values as JSON numbers (never null): +-inf as the largest finite
// magnitude, NaN as 0; the status says the values are not usable
void ReplaceNonFinite(nlohmann::json* j) {
  if (j->is_number_float()) {
    const double v = j->get<double>();
    if (std::isnan(v)) *j = 0.0;
    else if (std::isinf(v)) *j = v > 0 ? std::numeric_limits<double>::max() : std::numeric_limits<double>::lowest();
    return;
  }
  if (j->is_structured())
    for (auto& item : *j) ReplaceNonFinite(&item);
}


nlohmann::json SummaryObject(const Summary& s, UnitSystem system) {
  const OutputUnits u = UnitsOf(system);
  const double g = units::kStandardGravity;
  nlohmann::json j;
  j["units"] = {{"length", u.length_name}, {"speed", u.speed_name}, {"acceleration", "g"},
                {"energy", u.energy_name}, {"momentum", u.momentum_name}, {"time", "s"}, {"angle", "deg"}};
  for (const BodySummary& b : s.bodies) {
    j["bodies"].push_back({
        {"name", b.name},
        {"delta_v", b.delta_v * u.speed},
        {"delta_v_earth", Vector(b.delta_v_earth, u.speed)},
        {"delta_v_body", Vector(b.delta_v_body, u.speed)},
        {"pdof_deg", b.pdof_deg},
        {"pdof_clock", b.pdof_clock},
        {"peak_acceleration_g", b.peak_accel / g},
        {"average_acceleration_g", b.average_accel / g},
        {"max_crush", b.max_crush * u.length},
        {"max_crush_vertex", b.max_crush_vertex},
        {"max_crush_location_body", Vector(b.max_crush_location, u.length)},
        {"max_dynamic_crush", b.max_dynamic_crush * u.length},
        {"untaken_crush", b.untaken_crush * u.length},
        {"peak_contact_area", b.peak_contact_area * u.length * u.length},
        {"crush_energy", b.crush_energy * u.energy},
        {"friction_energy", b.friction_energy * u.energy},
        {"law_energy", b.law_energy * u.energy},
        {"support_work", b.support_work * u.energy},
        {"final_velocity_earth", Vector(b.final_velocity, u.speed)},
        {"final_yaw_rate_deg_s", b.final_yaw_rate * kRadToDeg},
        {"crush_profile", CrushProfileJson(b.crush_profile, u.length)},
    });
  }
  const ContactDiagnostics& d = s.diagnostics;
  j["overall"] = {
      {"status", RunStatusName(s.status)},
      {"end_time_s", s.end_time},
      {"momentum_before", Vector(s.momentum_before, u.momentum)},
      {"momentum_after", Vector(s.momentum_after, u.momentum)},
      {"kinetic_energy_before", s.kinetic_before * u.energy},
      {"kinetic_energy_after", s.kinetic_after * u.energy},
      {"crush_energy", s.crush_energy * u.energy},
      {"friction_energy", s.friction_energy * u.energy},
      {"law_energy", s.law_energy * u.energy},
      {"energy_discontinuity", s.energy_discontinuity * u.energy},
      {"support_work", s.support_work * u.energy},
      {"energy_balance_error", s.energy_balance_error},
      {"closing_speed", s.closing_speed * u.speed},
      {"separation_speed", s.separation_speed * u.speed},
      {"effective_restitution", s.main_pair >= 0 ? s.pairs[s.main_pair].restitution() : 0.0},
      {"contact_start_s", s.contact_start},
      {"contact_end_s", s.contact_end},
      {"steps", s.steps},
  };
  // every pair that touched, the main one's speeds repeated in "overall" above
  j["pairs"] = nlohmann::json::array();
  for (const PairSummary& p : s.pairs)
    j["pairs"].push_back({
        {"bodies", {p.a, p.b}},
        {"names", {s.bodies[p.a].name, s.bodies[p.b].name}},
        {"main", &p == &s.pairs[s.main_pair]},
        {"contact_start_s", p.contact_start},
        {"closing_speed", p.closing_speed * u.speed},
        {"separation_speed", p.separation_speed * u.speed},
        {"effective_restitution", p.restitution()},
        {"point_closing_speed", p.point_closing_speed * u.speed},
        {"point_separation_speed", p.point_separation_speed * u.speed},
        {"point_restitution", p.point_restitution()},
        {"impulse_ratio", p.impulse_ratio},
        {"yaw_rate_change_deg_s", {p.yaw_rate_change[0] * kRadToDeg, p.yaw_rate_change[1] * kRadToDeg}},
        {"friction_yaw_rate_change_deg_s",
         {p.friction_yaw_rate_change[0] * kRadToDeg, p.friction_yaw_rate_change[1] * kRadToDeg}},
    });
  j["warnings"] = nlohmann::json::array();
  for (const RunWarning& w : s.warnings) j["warnings"].push_back({{"code", w.code}, {"field", w.field}, {"message", w.message}});
  j["diagnostics"] = {{"candidates", d.candidates}, {"located", d.located}, {"touching", d.touching},
                      {"too_far_limited", d.too_far_limited}, {"max_crush_limited", d.max_crush_limited},
                      {"growth_limited", d.growth_limited}, {"held_unfound", d.held_unfound},
                      {"pushback_reduced", d.reduced}, {"faces_pushed", d.faces_pushed},
                      {"non_finite", d.non_finite}, {"pair_steps_in_contact", d.pairs_in_contact}};
  ReplaceNonFinite(&j);
  return j;
}

}  // namespace

std::string SummaryJson(const Summary& summary, const Scenario& scenario, const std::vector<std::string>& files) {
  nlohmann::json j = SummaryObject(summary, scenario.units);
  j["scenario"] = {{"file", scenario.file}, {"name", scenario.name}};
  j["files"] = files;
  return j.dump(2) + "\n";
}

}  // namespace dymesh
