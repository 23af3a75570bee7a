#include "attiguard/plan/initial_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

namespace attiguard::plan {

namespace {

using lie::Quat;

/// Clearance of the initial path beyond the margin [rad], and the check's sampling step.
constexpr double kClearance = 3.0 * std::numbers::pi / 180.0;
constexpr double kStep = 1.0 * std::numbers::pi / 180.0;
/// The roadmap: attitudes C exp(φ e) for C ∈ {R_0, R_mid, R_d}, e on a Fibonacci sphere.
constexpr int kDirections = 32;
constexpr std::array<double, 5> kMagnitudes{0.35, 0.7, 1.2, 1.8, 2.5};
/// Neighbours per roadmap attitude, and the cost of each segment beyond its angle [rad] (a
/// waypoint at rest costs time).
constexpr int kNeighbours = 14;
constexpr double kSegmentCost = 0.1;
/// A second way around must keep its waypoints this far from the first's [rad].
constexpr double kOtherWay = 0.5;

/// The rotation angle between two attitudes given by quaternions (either sign).
double attitude_distance(const Quat& a, const Quat& b) noexcept {
  return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b))));
}

/// q_a ⊗ exp(s log(q_aᶜ ⊗ q_b)) along the short way.
Quat geodesic(const Quat& q_a, const Quat& q_b, double s) noexcept {
  Quat rel = lie::quat_multiply(lie::quat_conjugate(q_a), q_b);
  if (rel(0) < 0.0) rel = -rel;
  const lie::Vec3 w = lie::rotation_vector_from_quat(rel);
  return lie::quat_multiply(q_a, lie::quat_from_rotation_vector(s * w));
}

/// Deterministic unit directions (Fibonacci sphere).
std::vector<lie::Vec3> fibonacci_directions(int n) {
  std::vector<lie::Vec3> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

bool attitude_is_free(const SlewProblem& problem, const Quat& q, double required) {
  const lie::Mat3 R = lie::quat_to_rotation(q);
  for (const governor::ConeConstraint& cone : problem.cones) {
    if (cone_angle_margin(cone, R) < required) return false;
  }
  return true;
}

/// The lazy roadmap (docs/slew-planner.md, "The initial path").
class Roadmap {
 public:
  Roadmap(const SlewProblem& problem, std::vector<Quat> nodes)
      : problem_(problem), nodes_(std::move(nodes)) {
    const int n = static_cast<int>(nodes_.size());
    neighbours_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      std::vector<std::pair<double, int>> d;
      for (int j = 0; j < n; ++j) {
        if (j != i) d.emplace_back(attitude_distance(nodes_[static_cast<std::size_t>(i)], nodes_[static_cast<std::size_t>(j)]), j);
      }
      const int k = std::min<int>(kNeighbours, static_cast<int>(d.size()));
      std::partial_sort(d.begin(), d.begin() + k, d.end());
      for (int m = 0; m < k; ++m) add_edge(i, d[static_cast<std::size_t>(m)].second);
    }
  }

  /// The cheapest path from node 0 to node 1 whose segments are all free, avoiding `banned`
  /// nodes; empty when none.
  std::vector<int> search(const std::vector<bool>& banned, int& checked) {
    for (;;) {
      const std::vector<int> path = cheapest(banned);
      if (path.empty()) return path;
      bool all_free = true;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        State& s = edge_state(path[i], path[i + 1]);
        if (s == State::unknown) {
          ++checked;
          s = segment_is_free(problem_, nodes_[static_cast<std::size_t>(path[i])],
                              nodes_[static_cast<std::size_t>(path[i + 1])], kClearance, kStep)
                  ? State::free
                  : State::blocked;
          edge_state(path[i + 1], path[i]) = s;
        }
        if (s == State::blocked) {
          all_free = false;
          break;
        }
      }
      if (all_free) return path;
    }
  }

  const std::vector<Quat>& nodes() const noexcept { return nodes_; }

 private:
  enum class State { unknown, free, blocked };
  struct Edge {
    int to;
    State state;
  };

  void add_edge(int a, int b) {
    for (const Edge& e : neighbours_[static_cast<std::size_t>(a)]) {
      if (e.to == b) return;
    }
    neighbours_[static_cast<std::size_t>(a)].push_back({b, State::unknown});
    neighbours_[static_cast<std::size_t>(b)].push_back({a, State::unknown});
  }
  State& edge_state(int a, int b) {
    for (Edge& e : neighbours_[static_cast<std::size_t>(a)]) {
      if (e.to == b) return e.state;
    }
    throw std::logic_error("roadmap: no such edge");
  }
  double cost(int a, int b) const noexcept {
    return attitude_distance(nodes_[static_cast<std::size_t>(a)], nodes_[static_cast<std::size_t>(b)]) + kSegmentCost;
  }
  std::vector<int> cheapest(const std::vector<bool>& banned) const {
    const int n = static_cast<int>(nodes_.size());
    std::vector<double> dist(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    std::vector<int> prev(static_cast<std::size_t>(n), -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    dist[0] = 0.0;
    open.emplace(0.0, 0);
    while (!open.empty()) {
      const auto [d, a] = open.top();
      open.pop();
      if (d > dist[static_cast<std::size_t>(a)]) continue;
      if (a == 1) break;
      for (const Edge& e : neighbours_[static_cast<std::size_t>(a)]) {
        if (e.state == State::blocked || banned[static_cast<std::size_t>(e.to)]) continue;
        const double nd = d + cost(a, e.to);
        if (nd < dist[static_cast<std::size_t>(e.to)]) {
          dist[static_cast<std::size_t>(e.to)] = nd;
          prev[static_cast<std::size_t>(e.to)] = a;
          open.emplace(nd, e.to);
        }
      }
    }
    if (!std::isfinite(dist[1])) return {};
    std::vector<int> path;
    for (int v = 1; v != -1; v = prev[static_cast<std::size_t>(v)]) path.push_back(v);
    std::reverse(path.begin(), path.end());
    return path;
  }

  const SlewProblem& problem_;
  std::vector<Quat> nodes_;
  std::vector<std::vector<Edge>> neighbours_;
};

/// Removes waypoints a free segment can skip (greedy shortcut from each kept waypoint to the
/// farthest one it sees).
std::vector<Quat> shortcut(const SlewProblem& problem, const std::vector<Quat>& path,
                           int& checked) {
  std::vector<Quat> out{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t next = i + 1;
    for (std::size_t j = path.size() - 1; j > i + 1; --j) {
      ++checked;
      if (segment_is_free(problem, path[i], path[j], kClearance, kStep)) {
        next = j;
        break;
      }
    }
    out.push_back(path[next]);
    i = next;
  }
  return out;
}

/// Sign-continuous waypoints and their total angle.
AttitudePath make_path(std::vector<Quat> waypoints) {
  AttitudePath out;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    if (waypoints[i].dot(waypoints[i - 1]) < 0.0) waypoints[i] = -waypoints[i];
    out.angle += attitude_distance(waypoints[i - 1], waypoints[i]);
  }
  out.waypoints = std::move(waypoints);
  return out;
}

}  // namespace

bool segment_is_free(const SlewProblem& problem, const Quat& q_a, const Quat& q_b,
                     double clearance, double step) {
  const double angle = attitude_distance(q_a, q_b);
  const Quat& q0 = lie::rotation_to_quat(problem.R_start);
  const Quat& qd = lie::rotation_to_quat(problem.R_target);
  const int n = std::max(1, static_cast<int>(std::ceil(angle / step)));
  for (int i = 0; i <= n; ++i) {
    const Quat q = geodesic(q_a, q_b, static_cast<double>(i) / n);
    const double to_end = std::min(attitude_distance(q, q0), attitude_distance(q, qd));
    const double required = problem.cone_margin + std::min(clearance, to_end);
    if (!attitude_is_free(problem, q, required)) return false;
  }
  return true;
}

PathSearch find_paths(const SlewProblem& problem, int count) {
  PathSearch out;
  const Quat q0 = lie::rotation_to_quat(problem.R_start);
  Quat qd = lie::rotation_to_quat(problem.R_target);
  if (qd.dot(q0) < 0.0) qd = -qd;
  out.attitudes = 2;
  ++out.segments_checked;
  if (segment_is_free(problem, q0, qd, kClearance, kStep)) {
    out.paths.push_back(make_path({q0, qd}));
    return out;
  }
  std::vector<Quat> nodes{q0, qd};
  const Quat q_mid = geodesic(q0, qd, 0.5);
  for (const Quat& centre : {q0, q_mid, qd}) {
    for (const lie::Vec3& e : fibonacci_directions(kDirections)) {
      for (double phi : kMagnitudes) {
        const Quat q = lie::quat_multiply(centre, lie::quat_from_rotation_vector(phi * e));
        if (attitude_is_free(problem, q, problem.cone_margin + kClearance)) nodes.push_back(q);
      }
    }
  }
  out.attitudes = static_cast<int>(nodes.size());
  Roadmap roadmap(problem, std::move(nodes));
  std::vector<bool> banned(roadmap.nodes().size(), false);
  for (int found = 0; found < count; ++found) {
    const std::vector<int> ids = roadmap.search(banned, out.segments_checked);
    if (ids.empty()) break;
    std::vector<Quat> waypoints;
    for (int id : ids) waypoints.push_back(roadmap.nodes()[static_cast<std::size_t>(id)]);
    out.paths.push_back(make_path(shortcut(problem, waypoints, out.segments_checked)));
    // Another way around: no waypoint near this path's waypoints.
    for (std::size_t j = 2; j < roadmap.nodes().size(); ++j) {
      for (std::size_t w = 1; w + 1 < out.paths.back().waypoints.size(); ++w) {
        if (attitude_distance(roadmap.nodes()[j], out.paths.back().waypoints[w]) < kOtherWay) {
          banned[j] = true;
        }
      }
    }
  }
  return out;
}

}  // namespace attiguard::plan
