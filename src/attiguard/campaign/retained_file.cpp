#include "attiguard/campaign/retained_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {
namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is 64-bit since HDF5 1.10");

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw InputError(path.string() + ": HDF5: " + what);
}

hid_t check(hid_t id, const std::filesystem::path& path, const char* what) {
  if (id < 0) fail(path, what);
  return id;
}

void write_attribute(hid_t obj, const char* name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(a);
  H5Sclose(space);
}

void write_attribute(hid_t obj, const char* name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, type, value.empty() ? "" : value.c_str());
  H5Aclose(a);
  H5Sclose(space);
  H5Tclose(type);
}

std::string read_string_attribute(hid_t obj, const char* name) {
  if (H5Aexists(obj, name) <= 0) return {};
  const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  const std::size_t n = H5Tget_size(type);
  std::string s(n, '\0');
  H5Aread(a, type, s.data());
  H5Tclose(type);
  H5Aclose(a);
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size() && !s.empty()) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

/// The dataset's 1-D or 2-D extent.
std::vector<hsize_t> extent(hid_t ds) {
  const hid_t space = H5Dget_space(ds);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank > 0 ? rank : 0));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  return dims;
}

/// Writes /t, the sample times [s].
void write_times(hid_t file, const std::vector<double>& times, const std::filesystem::path& path) {
  const hsize_t s = times.size();
  const hid_t space = H5Screate_simple(1, &s, nullptr);
  const hid_t ds = check(H5Dcreate2(file, "/t", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path, "cannot create /t");
  H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data());
  write_attribute(ds, "units", std::string("s"));
  H5Dclose(ds);
  H5Sclose(space);
}

/// Creates /series/NAME for each column: float64 [runs, samples], one chunk per run, deflated,
/// NaN where no run was written; the datasets are appended to `datasets` (left open).
void create_series(hid_t file, const std::vector<std::string>& columns, std::size_t runs,
                   hsize_t samples, const std::filesystem::path& path, std::vector<hid_t>& datasets) {
  const hid_t group = check(H5Gcreate2(file, "/series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path, "cannot create /series");
  const hsize_t dims[2] = {static_cast<hsize_t>(runs), samples};
  const hsize_t chunk[2] = {1, samples > 0 ? samples : 1};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(props, 2, chunk);
  H5Pset_deflate(props, 4);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  H5Pset_fill_value(props, H5T_NATIVE_DOUBLE, &nan);
  for (const auto& c : columns) {
    datasets.push_back(check(H5Dcreate2(group, c.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, props, H5P_DEFAULT),
                             path, "cannot create a dataset"));
  }
  H5Pclose(props);
  H5Sclose(space);
  H5Gclose(group);
}

}  // namespace

RetainedFile::RetainedFile(const std::filesystem::path& path, const std::vector<std::string>& columns,
                           const std::vector<double>& times, std::size_t runs, double interval,
                           bool keep_existing)
    : samples_(times.size()), runs_(runs), path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported as InputError
  std::error_code ec;
  std::optional<RetainedSeries> carried;  // the rows of a campaign extended by --resume
  if (keep_existing && std::filesystem::is_regular_file(path, ec)) {
    RetainedSeries old = read_retained(path);
    if (old.columns != columns || old.t != times) {
      fail(path, "--resume: the retained file has other columns or times than this campaign "
                 "(columns " + join(old.columns) + ", " + std::to_string(old.t.size()) +
                 " samples): the scenario's retain keys changed; remove the file or start a new --out");
    }
    if (old.runs != runs) carried = std::move(old);
  }
  if (keep_existing && !carried && std::filesystem::is_regular_file(path, ec)) {
    file_ = check(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), path, "cannot open for writing");
    for (const auto& c : columns) {
      datasets_.push_back(check(H5Dopen2(file_, ("/series/" + c).c_str(), H5P_DEFAULT), path, "no dataset"));
    }
    return;
  }
  file_ = check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path, "cannot create");
  const hsize_t s = times.size();
  write_times(file_, times, path);
  create_series(file_, columns, runs, s, path, datasets_);
  write_attribute(file_, "retain_interval", interval);
  write_attribute(file_, "runs", static_cast<double>(runs));
  write_attribute(file_, "samples", static_cast<double>(s));
  write_attribute(file_, "columns", join(columns));
  if (carried) {  // a larger (or smaller) --runs on --resume: keep the rows of the runs done
    const std::size_t S = times.size();
    std::vector<double> values(columns.size() * S);
    for (std::size_t k = 0; k < std::min(runs, carried->runs); ++k) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        std::copy_n(carried->values[c].begin() + static_cast<std::ptrdiff_t>(k * S), S,
                    values.begin() + static_cast<std::ptrdiff_t>(c * S));
      }
      write_run(k, values, S);
    }
  }
}

RetainedFile::~RetainedFile() {
  for (hid_t d : datasets_) H5Dclose(d);
  if (file_ >= 0) H5Fclose(file_);
}

void RetainedFile::write_run(std::size_t k, std::span<const double> values, std::size_t samples) {
  if (k >= runs_ || samples_ == 0) return;
  const std::size_t n = std::min(samples, samples_);
  std::vector<double> row(samples_, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < datasets_.size(); ++c) {
    for (std::size_t s = 0; s < n; ++s) row[s] = values[c * samples + s];
    const hid_t file_space = H5Dget_space(datasets_[c]);
    const hsize_t start[2] = {k, 0};
    const hsize_t count[2] = {1, samples_};
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hsize_t m = samples_;
    const hid_t mem = H5Screate_simple(1, &m, nullptr);
    const herr_t e = H5Dwrite(datasets_[c], H5T_NATIVE_DOUBLE, mem, file_space, H5P_DEFAULT, row.data());
    H5Sclose(mem);
    H5Sclose(file_space);
    if (e < 0) fail(path_, "cannot write run " + std::to_string(k));
  }
  H5Fflush(file_, H5F_SCOPE_LOCAL);
}

RetainedSeries read_retained(const std::filesystem::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) fail(path, "cannot open (not an HDF5 file?)");
  RetainedSeries r;
  r.columns = split_commas(read_string_attribute(f, "columns"));
  const hid_t t = H5Dopen2(f, "/t", H5P_DEFAULT);
  if (t < 0) {
    H5Fclose(f);
    fail(path, "no /t: not a retained.h5 of attiguard");
  }
  const auto te = extent(t);
  r.t.resize(te.empty() ? 0 : te[0]);
  if (!r.t.empty()) H5Dread(t, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, r.t.data());
  H5Dclose(t);
  for (const auto& c : r.columns) {
    const hid_t ds = H5Dopen2(f, ("/series/" + c).c_str(), H5P_DEFAULT);
    if (ds < 0) {
      H5Fclose(f);
      fail(path, "no /series/" + c);
    }
    const auto e = extent(ds);
    r.runs = e.size() == 2 ? e[0] : 0;
    std::vector<double> v(r.runs * r.t.size());
    if (!v.empty()) H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(ds);
    r.values.push_back(std::move(v));
  }
  H5Fclose(f);
  return r;
}

}  // namespace attiguard::campaign
