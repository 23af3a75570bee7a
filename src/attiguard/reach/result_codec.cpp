#include "attiguard/reach/result_codec.hpp"

#include <cstdint>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"

namespace attiguard::reach {

namespace {

using nlohmann::json;

template <class M>
json dense(const M& m) {
  json a = json::array();
  for (Eigen::Index i = 0; i < m.size(); ++i) a.push_back(m.data()[i]);
  return a;
}

template <class M>
void dense(const json& a, M& m) {
  if (!a.is_array() || static_cast<Eigen::Index>(a.size()) != m.size()) {
    throw NumericalError("reach result: array of the wrong size in a gathered cell");
  }
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = a[static_cast<std::size_t>(i)].get<double>();
}

json box(const Box3& b) { return {dense(b.lo), dense(b.hi)}; }
void box(const json& j, Box3& b) {
  dense(j.at(0), b.lo);
  dense(j.at(1), b.hi);
}
json ball(const AttitudeBall& b) { return {dense(b.center), b.radius}; }
void ball(const json& j, AttitudeBall& b) {
  dense(j.at(0), b.center);
  b.radius = j.at(1).get<double>();
}

/// A JSON array of the records, each encoded by `encode`.
template <class T, class Encode>
json array_of(const std::vector<T>& records, const Encode& encode) {
  json a = json::array();
  for (const T& r : records) a.push_back(encode(r));
  return a;
}

/// The records of a JSON array, each decoded by `decode`.
template <class T, class Decode>
std::vector<T> records_of(const json& a, const Decode& decode) {
  std::vector<T> out;
  for (const json& r : a) out.push_back(decode(r));
  return out;
}

json segment_json(const TubeSegment& g) { return {g.t0, g.t1, ball(g.attitude), box(g.omega), g.omega_norm}; }
TubeSegment segment_from(const json& g) {
  TubeSegment seg;
  seg.t0 = g.at(0).get<double>();
  seg.t1 = g.at(1).get<double>();
  ball(g.at(2), seg.attitude);
  box(g.at(3), seg.omega);
  // +∞ (no bound computed) travels as null through JSON/CBOR.
  seg.omega_norm = g.at(4).is_null() ? std::numeric_limits<double>::infinity() : g.at(4).get<double>();
  return seg;
}

json trial_json(const RateTrial& t) { return {t.c, t.feasible, t.enclosure_radius}; }
RateTrial trial_from(const json& t) {
  return {t.at(0).get<double>(), t.at(1).get<bool>(), t.at(2).get<double>()};
}

json nominal_json(const NominalPoint& p) { return {p.t, dense(p.R), dense(p.omega)}; }
NominalPoint nominal_from(const json& p) {
  NominalPoint n;
  n.t = p.at(0).get<double>();
  dense(p.at(1), n.R);
  dense(p.at(2), n.omega);
  return n;
}

json step_json(const ReachStep& s) {
  return {{"i", s.index}, {"t0", s.t0}, {"t1", s.t1}, {"wbox", box(s.omega_box)},
          {"abox", ball(s.attitude_box)}, {"tube", array_of(s.state_tube, segment_json)},
          {"c_id", s.c_identity}, {"c", s.c},
          {"Q", dense(s.Q)}, {"S", dense(s.S)}, {"P", dense(s.P)}, {"r", s.r}, {"R", dense(s.R)}, {"w", dense(s.omega)},
          {"ar", s.attitude_radius}, {"whw", dense(s.omega_half_widths)},
          {"na", s.numerical_allowance}, {"neR", s.nominal_error_R}, {"new", s.nominal_error_omega},
          {"exact", s.lmi_exact}, {"rho", s.lmi_rho},
          {"fb", s.fallback}, {"pr", s.proved_rigorously}, {"solves", s.sdp_solves},
          {"trials", array_of(s.trials, trial_json)}};
}

ReachStep step_from(const json& j) {
  ReachStep s;
  s.index = j.at("i").get<int>();
  s.t0 = j.at("t0").get<double>();
  s.t1 = j.at("t1").get<double>();
  box(j.at("wbox"), s.omega_box);
  ball(j.at("abox"), s.attitude_box);
  s.state_tube = records_of<TubeSegment>(j.at("tube"), segment_from);
  s.c_identity = j.at("c_id").get<double>();
  s.c = j.at("c").get<double>();
  dense(j.at("Q"), s.Q);
  dense(j.at("P"), s.P);
  dense(j.at("S"), s.S);
  s.r = j.at("r").get<double>();
  dense(j.at("R"), s.R);
  dense(j.at("w"), s.omega);
  s.attitude_radius = j.at("ar").get<double>();
  dense(j.at("whw"), s.omega_half_widths);
  s.numerical_allowance = j.at("na").get<double>();
  s.nominal_error_R = j.at("neR").get<double>();
  s.nominal_error_omega = j.at("new").get<double>();
  s.lmi_exact = j.at("exact").get<bool>();
  s.lmi_rho = j.at("rho").get<double>();
  s.proved_rigorously = j.at("pr").get<bool>();
  s.fallback = j.at("fb").get<bool>();
  s.sdp_solves = j.at("solves").get<int>();
  s.trials = records_of<RateTrial>(j.at("trials"), trial_from);
  return s;
}

}  // namespace

std::string encode_result(const ReachResult& r) {
  const InitialSet& in = r.initial;
  const json j = {{"init", {dense(in.R0), in.attitude_radius, dense(in.omega0), in.omega_radius, dense(in.P0)}},
                  {"Q0", dense(r.Q0)}, {"S0", dense(r.S0)}, {"P0", dense(r.P0)}, {"r0", r.r0},
                  {"steps", array_of(r.steps, step_json)}, {"nominal", array_of(r.nominal, nominal_json)},
                  {"solves", r.sdp_solves}, {"wall", r.wall_time_s},
                  {"done", {r.complete, r.stop_time, r.stop_reason, r.bisections, r.retries}}};
  const std::vector<std::uint8_t> bytes = json::to_cbor(j);
  return {bytes.begin(), bytes.end()};
}

ReachResult decode_result(const std::string& bytes) {
  try {
    const json j = json::from_cbor(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    ReachResult r;
    const json& in = j.at("init");
    dense(in.at(0), r.initial.R0);
    r.initial.attitude_radius = in.at(1).get<double>();
    dense(in.at(2), r.initial.omega0);
    r.initial.omega_radius = in.at(3).get<double>();
    dense(in.at(4), r.initial.P0);
    dense(j.at("Q0"), r.Q0);
    dense(j.at("P0"), r.P0);
    dense(j.at("S0"), r.S0);
    r.r0 = j.at("r0").get<double>();
    r.steps = records_of<ReachStep>(j.at("steps"), step_from);
    r.nominal = records_of<NominalPoint>(j.at("nominal"), nominal_from);
    r.sdp_solves = j.at("solves").get<int>();
    r.wall_time_s = j.at("wall").get<double>();
    const json& done = j.at("done");
    r.complete = done.at(0).get<bool>();
    r.stop_time = done.at(1).get<double>();
    r.stop_reason = done.at(2).get<std::string>();
    r.bisections = done.at(3).get<int>();
    r.retries = done.at(4).get<int>();
    return r;
  } catch (const json::exception& e) {
    throw NumericalError(std::string("reach result: malformed gathered cell: ") + e.what());
  }
}

}  // namespace attiguard::reach
