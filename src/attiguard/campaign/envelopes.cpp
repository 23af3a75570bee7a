#include "attiguard/campaign/envelopes.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "attiguard/campaign/aggregation.hpp"
#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {

Envelope envelope(const RetainedSeries& series, std::size_t c, std::size_t worst_count) {
  Envelope e;
  e.column = series.columns[c];
  const std::size_t S = series.t.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double>& v = series.values[c];
  std::vector<double> at;
  for (std::size_t s = 0; s < S; ++s) {
    at.clear();
    for (std::size_t k = 0; k < series.runs; ++k) {
      const double x = v[k * S + s];
      if (std::isfinite(x)) at.push_back(x);
    }
    std::sort(at.begin(), at.end());
    const bool any = !at.empty();
    e.min.push_back(any ? at.front() : nan);
    e.p1.push_back(any ? percentile(at, 1) : nan);
    e.p50.push_back(any ? percentile(at, 50) : nan);
    e.p99.push_back(any ? percentile(at, 99) : nan);
    e.max.push_back(any ? at.back() : nan);
    e.count.push_back(static_cast<double>(at.size()));
  }
  const bool low_is_bad = e.column.find("margin") != std::string::npos;
  std::vector<std::pair<double, std::size_t>> extreme;
  for (std::size_t k = 0; k < series.runs; ++k) {
    double m = low_is_bad ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    bool any = false;
    for (std::size_t s = 0; s < S; ++s) {
      const double x = v[k * S + s];
      if (!std::isfinite(x)) continue;
      any = true;
      m = low_is_bad ? std::min(m, x) : std::max(m, x);
    }
    if (any) extreme.emplace_back(low_is_bad ? m : -m, k);
  }
  std::sort(extreme.begin(), extreme.end());
  for (std::size_t i = 0; i < std::min(worst_count, extreme.size()); ++i) e.worst.push_back(extreme[i].second);
  return e;
}

void write_envelopes(const std::filesystem::path& path, const std::vector<Envelope>& envelopes) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) throw InputError(path.string() + ": HDF5: cannot open for writing");
  for (const char* g : {"/envelopes", "/worst"}) {
    if (H5Lexists(f, g, H5P_DEFAULT) > 0) H5Ldelete(f, g, H5P_DEFAULT);
    H5Gclose(H5Gcreate2(f, g, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  }
  bool ok = true;
  for (const Envelope& e : envelopes) {
    const hsize_t S = e.min.size();
    std::vector<double> rows;
    for (const auto* r : {&e.min, &e.p1, &e.p50, &e.p99, &e.max, &e.count}) rows.insert(rows.end(), r->begin(), r->end());
    const hsize_t dims[2] = {6, S};
    hid_t space = H5Screate_simple(2, dims, nullptr);
    hid_t ds = H5Dcreate2(f, ("/envelopes/" + e.column).c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ok = ok && ds >= 0 && (S == 0 || H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()) >= 0);
    if (ds >= 0) H5Dclose(ds);
    H5Sclose(space);
    std::vector<std::int64_t> worst(e.worst.begin(), e.worst.end());
    const hsize_t n = worst.size();
    space = H5Screate_simple(1, &n, nullptr);
    ds = H5Dcreate2(f, ("/worst/" + e.column).c_str(), H5T_NATIVE_INT64, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ok = ok && ds >= 0 && (n == 0 || H5Dwrite(ds, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, worst.data()) >= 0);
    if (ds >= 0) H5Dclose(ds);
    H5Sclose(space);
  }
  H5Fclose(f);
  if (!ok) throw InputError(path.string() + ": HDF5: cannot write the envelopes");
}

}  // namespace attiguard::campaign
