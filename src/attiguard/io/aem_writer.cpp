#include "attiguard/io/aem_writer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/partial_file.hpp"

namespace attiguard::io {
namespace {

/// A number of a data line: 17 significant digits (reads back to the same double).
std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.16e", v);
  return buf;
}

void key(std::string& out, const char* name, const std::string& value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%-20s= ", name);
  out += buf;
  out += value;
  out += '\n';
}

const char* attitude_type(const AemMetadata& m) {
  if (!m.with_rates) return "QUATERNION";
  return m.version == AemVersion::v1 ? "QUATERNION/RATE" : "QUATERNION/ANGVEL";
}

/// The data line of one sample: time tag, quaternion (QC ≥ 0) in the version's order, rates.
std::string data_line(const AemMetadata& m, const AttitudeSample& s) {
  const double sign = s.q_ib[0] < 0.0 ? -1.0 : 1.0;
  const double qc = sign * s.q_ib[0], q1 = sign * s.q_ib[1], q2 = sign * s.q_ib[2],
               q3 = sign * s.q_ib[3];
  std::string line = format_calendar_time(add_seconds(m.epoch, s.t), kAemTimeDecimals);
  const double v1[4] = {qc, q1, q2, q3};
  const double v2[4] = {q1, q2, q3, qc};
  for (double v : m.version == AemVersion::v1 ? v1 : v2) line += ' ' + number(v);
  if (m.with_rates) {
    constexpr double kDeg = 180.0 / std::numbers::pi;
    for (double w : s.omega_b) line += ' ' + number(w * kDeg);
  }
  return line + '\n';
}

void check_samples(std::span<const AttitudeSample> samples) {
  if (samples.empty()) throw InputError("AEM export: the trajectory has no rows");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const AttitudeSample& s = samples[i];
    bool finite = std::isfinite(s.t);
    for (double v : s.q_ib) finite = finite && std::isfinite(v);
    for (double v : s.omega_b) finite = finite && std::isfinite(v);
    if (!finite) {
      throw InputError("AEM export: row " + std::to_string(i + 1) + " (t = " + number(s.t) +
                       ") has a value that is not finite");
    }
    if (i > 0 && !(s.t > samples[i - 1].t)) {
      throw InputError("AEM export: row " + std::to_string(i + 1) + ": t = " + number(s.t) +
                       " does not increase (CCSDS 504.0-B-1 4.2.5.4.1)");
    }
  }
}

}  // namespace

std::string aem_text(const AemMetadata& m, std::span<const AttitudeSample> samples,
                     const CalendarTime& created) {
  check_samples(samples);
  const bool v1 = m.version == AemVersion::v1;
  std::string out;
  key(out, "CCSDS_AEM_VERS", v1 ? "1.0" : "2.0");
  key(out, "CREATION_DATE", format_calendar_time(created, 0));
  key(out, "ORIGINATOR", m.originator);
  out += '\n';
  out += "META_START\n";
  for (const std::string& c : m.comments) out += "COMMENT " + c + '\n';
  if (!v1) {
    out += "COMMENT quaternion: coordinate transformation REF_FRAME_A to REF_FRAME_B, Q1 Q2 Q3 QC "
           "(504.0-B-2)\n";
  }
  key(out, "OBJECT_NAME", m.object_name);
  key(out, "OBJECT_ID", m.object_id);
  key(out, "CENTER_NAME", m.center_name);
  key(out, "REF_FRAME_A", m.ref_frame_a);
  key(out, "REF_FRAME_B", m.ref_frame_b);
  if (v1) key(out, "ATTITUDE_DIR", "A2B");
  key(out, "TIME_SYSTEM", m.time_system);
  key(out, "START_TIME", format_calendar_time(add_seconds(m.epoch, samples.front().t), kAemTimeDecimals));
  key(out, "STOP_TIME", format_calendar_time(add_seconds(m.epoch, samples.back().t), kAemTimeDecimals));
  key(out, "ATTITUDE_TYPE", attitude_type(m));
  if (v1) key(out, "QUATERNION_TYPE", "FIRST");
  if (m.with_rates) key(out, v1 ? "RATE_FRAME" : "ANGVEL_FRAME", v1 ? "REF_FRAME_B" : m.ref_frame_b);
  out += "META_STOP\n\n";
  out += "DATA_START\n";
  for (const AttitudeSample& s : samples) out += data_line(m, s);
  out += "DATA_STOP\n";
  return out;
}

void write_aem(const std::filesystem::path& path, const AemMetadata& meta,
               std::span<const AttitudeSample> samples) {
  const auto now = std::chrono::time_point_cast<std::chrono::seconds>(std::chrono::system_clock::now());
  const CalendarTime created{static_cast<std::int64_t>(now.time_since_epoch().count()), 0.0};
  const std::string text = aem_text(meta, samples, created);
  {
    std::ofstream out(partial_path(path), std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write " + path.string() + ": " + std::strerror(errno));
    out << text;
    out.flush();
    if (!out) throw InputError("cannot write " + path.string() + ": write failed");
  }
  commit_partial(path);
}

}  // namespace attiguard::io
