#include "attiguard/reach/closed_loop.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <stdexcept>

namespace attiguard::reach {

namespace {

/// |B| rad(ω) for an interval B over a box, plus the mean-value bound of the A-term.
Box3 mean_value_box(const Vec3& center_value, const IntervalMat3& A, double rho,
                    const IntervalMat3& B, const Box3& box) {
  const Mat3 Aabs = A.abs_max();
  const Mat3 Babs = B.abs_max();
  Vec3 rad = Babs * box.radius();
  for (int k = 0; k < 3; ++k) {
    rad(k) += Aabs.row(k).norm() * rho;
  }
  return Box3::around(center_value, rad);
}

/// G_k = J⁻¹((J e_k)^ − ê_k J): the gyroscopic Jacobian is Σ_k ω_k G_k.
std::array<Mat3, 3> gyroscopic_basis(const Mat3& J, const Mat3& Jinv) {
  std::array<Mat3, 3> G;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    G[static_cast<std::size_t>(k)] = Jinv * (lie::hat(J * e) - lie::hat(e) * J);
  }
  return G;
}

/// Interval of Σ_k ω_k G_k over a box (exact: linear in ω).
IntervalMat3 gyroscopic_enclosure(const std::array<Mat3, 3>& G, const Box3& box) {
  const Vec3 c = box.center();
  const Vec3 r = box.radius();
  Mat3 center = Mat3::Zero();
  Mat3 rad = Mat3::Zero();
  for (int k = 0; k < 3; ++k) {
    center += c(k) * G[static_cast<std::size_t>(k)];
    rad += r(k) * G[static_cast<std::size_t>(k)].cwiseAbs();
  }
  return IntervalMat3::around(center, rad);
}

Mat3 invert_checked(const Mat3& J, const char* what) {
  if (!J.allFinite() || std::abs(J.determinant()) < 1e-300) {
    throw std::invalid_argument(std::string(what) + ": singular or non-finite matrix");
  }
  return J.inverse();
}

}  // namespace

Box3 ClosedLoop::omega_dot_enclosure(const AttitudeBall& att, const Box3& box) const {
  return mean_value_box(omega_dot(att.center, box.center()), A_enclosure(att, box), att.radius,
                        B_enclosure(att, box), box);
}

// ---- LinearOmegaLoop -------------------------------------------------------------------------

LinearOmegaLoop::LinearOmegaLoop(const Mat3& M) : M_(M) {
  if (!M.allFinite()) throw std::invalid_argument("linear_omega: non-finite matrix");
}
Vec3 LinearOmegaLoop::omega_dot(const Mat3&, const Vec3& omega) const { return M_ * omega; }
Mat3 LinearOmegaLoop::A(const Mat3&, const Vec3&) const { return Mat3::Zero(); }
Mat3 LinearOmegaLoop::B(const Mat3&, const Vec3&) const { return M_; }
IntervalMat3 LinearOmegaLoop::A_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(Mat3::Zero());
}
IntervalMat3 LinearOmegaLoop::B_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(M_);
}
PolynomialField LinearOmegaLoop::polynomial_field() const {
  PolynomialField f;
  f.linear = M_;
  return f;
}
LmiEnclosure LinearOmegaLoop::lmi_enclosure(const AttitudeBall&, const Box3& box) const {
  // A = 0 and B = M are constant and ω̂ is linear in ω: the 8 vertices are exact.
  LmiEnclosure e;
  e.exact = true;
  for (int v = 0; v < 8; ++v) e.vertices.push_back({box.vertex(v), Mat3::Zero(), M_});
  return e;
}

// ---- RigidBodyLoop ---------------------------------------------------------------------------

RigidBodyLoop::RigidBodyLoop(const Mat3& J, const Vec3& torque_b)
    : J_(J), Jinv_(invert_checked(J, "rigid body inertia")), tau_(torque_b),
      G_(gyroscopic_basis(J_, Jinv_)) {
  if (!torque_b.allFinite()) throw std::invalid_argument("rigid body: non-finite torque");
}
std::string RigidBodyLoop::name() const { return tau_.isZero(0.0) ? "free" : "constant_torque"; }
Vec3 RigidBodyLoop::omega_dot(const Mat3&, const Vec3& w) const {
  return Jinv_ * (-w.cross(J_ * w) + tau_);
}
Mat3 RigidBodyLoop::A(const Mat3&, const Vec3&) const { return Mat3::Zero(); }
Mat3 RigidBodyLoop::B(const Mat3&, const Vec3& w) const {
  return Jinv_ * (lie::hat(J_ * w) - lie::hat(w) * J_);
}
IntervalMat3 RigidBodyLoop::A_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(Mat3::Zero());
}
IntervalMat3 RigidBodyLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  return gyroscopic_enclosure(G_, box);
}
PolynomialField RigidBodyLoop::polynomial_field() const {
  PolynomialField f;
  f.constant = Jinv_ * tau_;
  f.quadratic = gyroscopic_quadratic(J_, Jinv_);
  return f;
}
LmiEnclosure RigidBodyLoop::lmi_enclosure(const AttitudeBall&, const Box3& box) const {
  // A = 0, B is linear in ω, ω̂ is linear in ω, nothing depends on R: vertices are exact.
  LmiEnclosure e;
  e.exact = true;
  for (int v = 0; v < 8; ++v) {
    const Vec3 w = box.vertex(v);
    e.vertices.push_back({w, Mat3::Zero(), B(Mat3::Identity(), w)});
  }
  return e;
}

// ---- PdLoop ----------------------------------------------------------------------------------

PdLoop::PdLoop(const Mat3& J, double kp, double kd, const Mat3& R_g)
    : J_(J), Jinv_(invert_checked(J, "pd inertia")), Rg_(R_g), kp_(kp), kd_(kd),
      G_(gyroscopic_basis(J_, Jinv_)) {
  if (!std::isfinite(kp) || !std::isfinite(kd) || !R_g.allFinite()) {
    throw std::invalid_argument("pd: non-finite gains or reference");
  }
}
Vec3 PdLoop::omega_dot(const Mat3& R, const Vec3& w) const {
  const Mat3 E = R.transpose() * Rg_;
  const Vec3 tau = kp_ * lie::vee(lie::sk(E)) - kd_ * w;
  return Jinv_ * (-w.cross(J_ * w) + tau);
}
Mat3 PdLoop::A(const Mat3& R, const Vec3&) const {
  // d/dt vee(sk(exp(−tα̂) E)) = −½ vee(α̂E + Eᵀα̂) = −½ (tr(E) I − E) α.
  const Mat3 E = R.transpose() * Rg_;
  return -0.5 * kp_ * Jinv_ * (E.trace() * Mat3::Identity() - E);
}
Mat3 PdLoop::B(const Mat3&, const Vec3& w) const {
  return Jinv_ * (lie::hat(J_ * w) - lie::hat(w) * J_ - kd_ * Mat3::Identity());
}
IntervalMat3 PdLoop::A_enclosure(const AttitudeBall& att, const Box3&) const {
  // R = R_c exp(η̂), ‖η‖ ≤ ρ: E = exp(−η̂) E_c, ‖ΔE‖₂ ≤ 2 sin(ρ/2) =: s, so |ΔE_jk| ≤ s;
  // tr E = 1 + 2 cos θ_E with |θ_E − θ_Ec| ≤ ρ: |Δ tr E| ≤ min(2ρ, √6 s).
  const Mat3 Ac = A(att.center, Vec3::Zero());
  const double s = chord(att.radius);
  const double dtr = std::min(2.0 * att.radius, std::sqrt(6.0) * s);
  const Mat3 dD = 0.5 * (dtr * Mat3::Identity() + s * Mat3::Ones());
  return IntervalMat3::around(Ac, kp_ * Jinv_.cwiseAbs() * dD);
}
double PdLoop::a_deviation_bound(const AttitudeBall& att) const {
  const double s = chord(att.radius);
  const double dtr = std::min(2.0 * att.radius, std::sqrt(6.0) * s);
  Eigen::JacobiSVD<Mat3> svd(Jinv_);
  const double spectral = kp_ * svd.singularValues()(0) * 0.5 * (dtr + s);
  const double frobenius = A_enclosure(att, Box3{}).radius().norm();
  return std::min(spectral, frobenius);
}
IntervalMat3 PdLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  IntervalMat3 g = gyroscopic_enclosure(G_, box);
  const Mat3 damp = kd_ * Jinv_;
  return {g.lo - damp, g.hi - damp};
}
PolynomialField PdLoop::polynomial_field() const {
  PolynomialField f;
  f.linear = -kd_ * Jinv_;
  f.quadratic = gyroscopic_quadratic(J_, Jinv_);
  // k_p J⁻¹ vee(sk(RᵀR_g)) is linear in R: one column per entry R_rs.
  for (int r = 0; r < 3; ++r) {
    for (int s = 0; s < 3; ++s) {
      Mat3 unit = Mat3::Zero();
      unit(r, s) = 1.0;
      f.linear_R.col(3 * r + s) = kp_ * Jinv_ * lie::vee(lie::sk(unit.transpose() * Rg_));
    }
  }
  return f;
}
LmiEnclosure PdLoop::lmi_enclosure(const AttitudeBall& att, const Box3& box) const {
  // B and ω̂ are affine in ω and independent of R: vertices of the box, exact. A depends on R
  // only: its centre at every vertex and ‖A − A_c‖₂ ≤ rho handled by the robust LMI.
  LmiEnclosure e;
  e.exact = false;
  const Mat3 Ac = A(att.center, Vec3::Zero());
  for (int v = 0; v < 8; ++v) {
    const Vec3 w = box.vertex(v);
    e.vertices.push_back({w, Ac, B(Mat3::Identity(), w)});
  }
  e.rho = a_deviation_bound(att);
  return e;
}

}  // namespace attiguard::reach
