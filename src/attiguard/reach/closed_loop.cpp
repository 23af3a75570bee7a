#include "attiguard/reach/closed_loop.hpp"

#include <cmath>
#include <stdexcept>

#include "attiguard/core/errors.hpp"

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


}  // namespace

PolynomialField ClosedLoop::polynomial_field() const {
  const std::optional<PolynomialField> f =
      probe_polynomial_field([this](const Mat3& R, const Vec3& w) { return omega_dot(R, w); });
  if (!f) {
    throw NumericalError("ConReach: closed loop '" + name() +
                         "' is not a polynomial c + B w + (w^T Q_a w) + L vec(R) (reach/polynomial_field.hpp)");
  }
  return *f;
}

Box3 ClosedLoop::omega_dot_enclosure(const AttitudeBall& att, const Box3& box) const {
  return mean_value_box(omega_dot(att.center, box.center()), A_enclosure(att, box), att.radius,
                        B_enclosure(att, box), box);
}

// ---- LinearOmegaLoop -------------------------------------------------------------------------

LinearOmegaLoop::LinearOmegaLoop(const Mat3& M)
    : ClosedLoop({.lmi_depends_on_attitude = false, .omega_flow_affine = true}), M_(M) {
  if (!M.allFinite()) throw InputError("linear_omega: non-finite matrix");
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
LmiEnclosure LinearOmegaLoop::lmi_enclosure(const AttitudeBall&, const Box3& box) const {
  // A = 0 and B = M are constant and ω̂ is linear in ω: the 8 vertices are exact.
  LmiEnclosure e;
  e.exact = true;
  for (int v = 0; v < 8; ++v) e.vertices.push_back({box.vertex(v), Mat3::Zero(), M_});
  return e;
}

// ---- RigidBodyLoop ---------------------------------------------------------------------------

RigidBodyLoop::RigidBodyLoop(const Mat3& J, const Vec3& torque_b)
    : ClosedLoop({.lmi_depends_on_attitude = false, .omega_flow_affine = false}),
      body_(J), tau_(torque_b), G_(gyroscopic_basis(J, body_.inertia_inverse())) {
  if (!torque_b.allFinite()) throw InputError("rigid body: non-finite torque");
}
std::string RigidBodyLoop::name() const { return tau_.isZero(0.0) ? "free" : "constant_torque"; }
Vec3 RigidBodyLoop::omega_dot(const Mat3&, const Vec3& w) const {
  return body_.angular_acceleration(w, tau_);
}
Mat3 RigidBodyLoop::A(const Mat3&, const Vec3&) const { return Mat3::Zero(); }
Mat3 RigidBodyLoop::B(const Mat3&, const Vec3& w) const {
  const Mat3& J = body_.inertia();
  return body_.inertia_inverse() * (lie::hat(J * w) - lie::hat(w) * J);
}
IntervalMat3 RigidBodyLoop::A_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(Mat3::Zero());
}
IntervalMat3 RigidBodyLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  return gyroscopic_enclosure(G_, box);
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
    : ClosedLoop({.lmi_depends_on_attitude = true, .omega_flow_affine = false}),
      body_(J), Rg_(R_g), gains_{kp, kd}, G_(gyroscopic_basis(J, body_.inertia_inverse())) {
  if (!std::isfinite(kp) || !std::isfinite(kd) || !R_g.allFinite()) {
    throw InputError("pd: non-finite gains or reference");
  }
}
Vec3 PdLoop::omega_dot(const Mat3& R, const Vec3& w) const {
  return body_.angular_acceleration(w, control::pd_torque(R, w, Rg_, gains_));
}
Mat3 PdLoop::A(const Mat3& R, const Vec3&) const {
  // d/dt vee(sk(exp(−tα̂) E)) = −½ vee(α̂E + Eᵀα̂) = −½ (tr(E) I − E) α.
  const Mat3 E = R.transpose() * Rg_;
  return -0.5 * gains_.kp * body_.inertia_inverse() * (E.trace() * Mat3::Identity() - E);
}
Mat3 PdLoop::B(const Mat3&, const Vec3& w) const {
  const Mat3& J = body_.inertia();
  return body_.inertia_inverse() * (lie::hat(J * w) - lie::hat(w) * J - gains_.kd * Mat3::Identity());
}
IntervalMat3 PdLoop::A_enclosure(const AttitudeBall& att, const Box3&) const {
  // R = R_c exp(η̂), ‖η‖ ≤ ρ: E = exp(−η̂) E_c, ‖ΔE‖₂ ≤ 2 sin(ρ/2) =: s, so |ΔE_jk| ≤ s;
  // tr E = 1 + 2 cos θ_E with |θ_E − θ_Ec| ≤ ρ: |Δ tr E| ≤ min(2ρ, √6 s).
  const Mat3 Ac = A(att.center, Vec3::Zero());
  const double s = chord(att.radius);
  const double dtr = std::min(2.0 * att.radius, std::sqrt(6.0) * s);
  const Mat3 dD = 0.5 * (dtr * Mat3::Identity() + s * Mat3::Ones());
  return IntervalMat3::around(Ac, gains_.kp * body_.inertia_inverse().cwiseAbs() * dD);
}
double PdLoop::a_deviation_bound(const AttitudeBall& att) const {
  const double s = chord(att.radius);
  const double dtr = std::min(2.0 * att.radius, std::sqrt(6.0) * s);
  // ‖J⁻¹‖₂ = 1/λ_min(J).
  const double spectral = gains_.kp / body_.min_principal_moment() * 0.5 * (dtr + s);
  const double frobenius = A_enclosure(att, Box3{}).radius().norm();
  return std::min(spectral, frobenius);
}
IntervalMat3 PdLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  IntervalMat3 g = gyroscopic_enclosure(G_, box);
  const Mat3 damp = gains_.kd * body_.inertia_inverse();
  return {g.lo - damp, g.hi - damp};
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
