#include "attiguard/io/aem_reader.hpp"

#include <charconv>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "attiguard/core/errors.hpp"

namespace attiguard::io {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

/// "'TEXT' WHAT" (built by append: GCC 12 warns falsely on "'" + std::string(…) chains).
std::string quoted(std::string_view text, std::string_view what) {
  std::string m;
  m.reserve(text.size() + what.size() + 3);
  m.append(1, '\'').append(text).append("' ").append(what);
  return m;
}

class Parser {
 public:
  Parser(std::string_view name, std::string_view epoch) : name_(name), epoch_text_(epoch) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(std::string(name_) + ":" + std::to_string(line) + ": " + what);
  }

  double number(std::size_t line, std::string_view text) const {
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size()) {
      fail(line, quoted(text, "is not a number"));
    }
    return v;
  }

  CalendarTime time(std::size_t line, std::string_view text) const {
    const auto t = parse_calendar_time(text);
    if (!t) fail(line, quoted(text, "is not a time tag YYYY-MM-DDThh:mm:ss[.d...]"));
    return *t;
  }

  AemFile parse(std::string_view text) {
    enum class Part { header, meta, between, data, done } part = Part::header;
    std::map<std::string, std::string, std::less<>> header, meta;
    std::size_t line_no = 0, pos = 0;
    std::vector<std::pair<std::size_t, std::string_view>> data;
    while (pos <= text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view line = trim(text.substr(pos, end - pos));
      pos = end + 1;
      ++line_no;
      if (line.empty()) continue;
      if (line.starts_with("COMMENT")) {
        if (part == Part::meta) file_.metadata.comments.emplace_back(trim(line.substr(7)));
        continue;
      }
      if (line == "META_START") {
        if (part != Part::header) fail(line_no, "only one segment is supported");
        part = Part::meta;
      } else if (line == "META_STOP") {
        if (part != Part::meta) fail(line_no, "META_STOP without META_START");
        part = Part::between;
      } else if (line == "DATA_START") {
        if (part != Part::between) fail(line_no, "DATA_START before the metadata block");
        part = Part::data;
      } else if (line == "DATA_STOP") {
        if (part != Part::data) fail(line_no, "DATA_STOP without DATA_START");
        part = Part::done;
      } else if (part == Part::data) {
        data.emplace_back(line_no, line);
      } else if (part == Part::header || part == Part::meta) {
        const std::size_t eq = line.find('=');
        if (eq == std::string_view::npos) fail(line_no, "expected KEY = VALUE");
        auto& table = part == Part::header ? header : meta;
        table[std::string(trim(line.substr(0, eq)))] = std::string(trim(line.substr(eq + 1)));
      } else {
        fail(line_no, "unexpected line outside the blocks");
      }
      if (pos > text.size()) break;
    }
    if (part != Part::done) fail(line_no, "the message ends before DATA_STOP");
    read_keys(header, meta, line_no);
    read_data(data);
    return file_;
  }

 private:
  static std::string take(std::map<std::string, std::string, std::less<>>& t, const char* key) {
    const auto it = t.find(key);
    return it == t.end() ? std::string() : it->second;
  }

  std::string required(std::map<std::string, std::string, std::less<>>& t, const char* key,
                       std::size_t line) const {
    std::string v = take(t, key);
    if (v.empty()) fail(line, std::string("missing obligatory key ") + key);
    return v;
  }

  void read_keys(std::map<std::string, std::string, std::less<>>& header,
                 std::map<std::string, std::string, std::less<>>& meta, std::size_t line) {
    AemMetadata& m = file_.metadata;
    const std::string vers = required(header, "CCSDS_AEM_VERS", line);
    if (vers == "1.0") {
      m.version = AemVersion::v1;
    } else if (vers == "2.0") {
      m.version = AemVersion::v2;
    } else {
      fail(line, "CCSDS_AEM_VERS = " + vers + " (expected 1.0 or 2.0)");
    }
    const bool v1 = m.version == AemVersion::v1;
    file_.creation_date = required(header, "CREATION_DATE", line);
    m.originator = required(header, "ORIGINATOR", line);
    m.object_name = required(meta, "OBJECT_NAME", line);
    m.object_id = required(meta, "OBJECT_ID", line);
    m.center_name = take(meta, "CENTER_NAME");
    m.ref_frame_a = required(meta, "REF_FRAME_A", line);
    m.ref_frame_b = required(meta, "REF_FRAME_B", line);
    m.time_system = required(meta, "TIME_SYSTEM", line);
    file_.start_time = required(meta, "START_TIME", line);
    file_.stop_time = required(meta, "STOP_TIME", line);
    const std::string type = required(meta, "ATTITUDE_TYPE", line);
    if (v1) {
      file_.attitude_dir = required(meta, "ATTITUDE_DIR", line);
      if (file_.attitude_dir != "A2B" && file_.attitude_dir != "B2A") {
        fail(line, "ATTITUDE_DIR = " + file_.attitude_dir + " (expected A2B or B2A)");
      }
      file_.quaternion_type = required(meta, "QUATERNION_TYPE", line);
      if (file_.quaternion_type != "FIRST" && file_.quaternion_type != "LAST") {
        fail(line, "QUATERNION_TYPE = " + file_.quaternion_type + " (expected FIRST or LAST)");
      }
    }
    if (type == "QUATERNION") {
      m.with_rates = false;
    } else if ((v1 && type == "QUATERNION/RATE") || (!v1 && type == "QUATERNION/ANGVEL")) {
      m.with_rates = true;
    } else {
      fail(line, "ATTITUDE_TYPE = " + type + " is not supported (QUATERNION, QUATERNION/RATE in "
                                             "1.0, QUATERNION/ANGVEL in 2.0)");
    }
  }

  void read_data(const std::vector<std::pair<std::size_t, std::string_view>>& data) {
    const AemMetadata& m = file_.metadata;
    const std::size_t expected = m.with_rates ? 8 : 5;
    bool have_epoch = false;
    CalendarTime epoch{};
    if (!epoch_text_.empty()) {
      epoch = time(0, epoch_text_);
      have_epoch = true;
    }
    const bool scalar_first = m.version == AemVersion::v1 && file_.quaternion_type == "FIRST";
    const bool b2a = file_.attitude_dir == "B2A";
    constexpr double kRad = std::numbers::pi / 180.0;
    for (const auto& [line, text] : data) {
      const auto f = fields(text);
      if (f.size() != expected) {
        fail(line, "expected " + std::to_string(expected) + " fields, found " +
                       std::to_string(f.size()));
      }
      const CalendarTime tag = time(line, f[0]);
      if (!have_epoch) {
        epoch = tag;
        have_epoch = true;
      }
      AttitudeSample s;
      s.t = seconds_between(epoch, tag);
      double q[4];
      for (int i = 0; i < 4; ++i) q[i] = number(line, f[1 + static_cast<std::size_t>(i)]);
      // Hamilton q_ib: scalar q_w = QC, vector = (Q1, Q2, Q3) for A2B; B2A is the inverse.
      s.q_ib = scalar_first ? std::array<double, 4>{q[0], q[1], q[2], q[3]}
                            : std::array<double, 4>{q[3], q[0], q[1], q[2]};
      if (b2a) {
        for (int i = 1; i < 4; ++i) s.q_ib[static_cast<std::size_t>(i)] *= -1.0;
      }
      if (m.with_rates) {
        for (int i = 0; i < 3; ++i) {
          s.omega_b[static_cast<std::size_t>(i)] = number(line, f[5 + static_cast<std::size_t>(i)]) * kRad;
        }
      }
      file_.samples.push_back(s);
    }
  }

  std::string_view name_;
  std::string_view epoch_text_;
  AemFile file_;
};

}  // namespace

AemFile parse_aem(std::string_view text, std::string_view name, std::string_view epoch) {
  return Parser(name, epoch).parse(text);
}

AemFile read_aem(const std::filesystem::path& path, std::string_view epoch) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_aem(ss.str(), path.string(), epoch);
}

}  // namespace attiguard::io
