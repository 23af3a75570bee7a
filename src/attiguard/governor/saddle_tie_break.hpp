#pragma once
/// @file saddle_tie_break.hpp
/// The saddle tie-break of the navigation field (docs/pet-erg.md, section 4, "Saddles: the
/// tie-break"; issue 41). A keep-out cone centred on the path of R_g towards R_d makes ρ_a and the
/// cone's ρ_r exactly opposite: ρ_n = ρ_a + Σρ_r (PET-ERG paper, Sec. III-B.2) vanishes at a
/// saddle of P short of R_d and the reference stops there. At the sampling instants t_k of
/// [PET-ERG eq. (5)] (held on [t_k, t_{k+1}) like the trigger flag) a balanced field inside an
/// active repulsive band starts a detour: the field becomes ρ_n + σ g ‖ρ_a‖ ĥ_i, with
/// ĥ_i = unit(a_cb − c a_b), a_cb = R_gᵀa_c,i, a direction perpendicular to a_b and to
/// g_c = a_b × a_cb: rotating R_g about it moves the body axis sideways around the cone, tangent
/// to the level set of c_i. Safety still rests on Γ and the DSM (they bound ‖ξ‖ whatever its
/// direction); the detour is bounded by g‖ρ_a‖ ≤ g while ρ_r diverges at c = δ.
/// Everything here is noexcept and allocation-free.

#include <span>

#include "attiguard/governor/cone_constraint.hpp"

namespace attiguard::governor {

/// Detection: the field is balanced when ‖ρ_n‖ ≤ kTieBreakBalance ‖ρ_a‖.
inline constexpr double kTieBreakBalance = 0.1;
/// Release: the natural field's own component along σĥ reaches kTieBreakRelease ‖ρ_a‖.
inline constexpr double kTieBreakRelease = 0.1;
/// The detour's weight g: the field while active is ρ_n + σ g ‖ρ_a‖ ĥ.
inline constexpr double kTieBreakDetourGain = 0.5;
/// Detection: a tangential component |ρ_nᵀĥ| above this fraction of ‖ρ_a‖ takes R_g around the
/// cone by itself (ξ is normalised), no tie-break is needed.
inline constexpr double kTieBreakClearTangent = 1e-3;
/// The side: P is compared at R_g exp(±kTieBreakProbe ĥ) [rad].
inline constexpr double kTieBreakProbe = 0.05;
/// The largest floor on ‖ρ_a‖ = sin d(R_g, R_d) below which no detour starts (R_g at R_d): the
/// governor passes its ε, which a slow flight loop derives above 1 (docs/pet-erg.md, section 8),
/// where ‖ρ_a‖ ≤ 1 could never exceed it; capped here (sin 2.9°).
inline constexpr double kTieBreakFloorCap = 0.05;

/// The tie-break state held on [t_k, t_{k+1}) (docs/pet-erg.md, section 4, "Saddles: the
/// tie-break"): whether a detour is active, around which cone (index into the governor's cones)
/// and on which side (σ = ±1).
struct TieBreak {
  bool active{false};
  int cone{-1};
  double sign{1.0};
};

/// ĥ = unit(a_cb − c a_b), a_cb = R_gᵀa_c (body frame), c = a_bᵀa_cb: the unit direction
/// perpendicular to a_b and to g_c = a_b × a_cb (PET-ERG paper Sec. III-B.2; docs/pet-erg.md,
/// section 4, "Saddles: the tie-break"). Zero when a_b is (anti)parallel to a_cb.
[[nodiscard]] Vec3 tie_break_direction(const ConeConstraint& cone, const Mat3& R_g) noexcept;

/// What update_tie_break decided at a sampling instant (docs/pet-erg.md, section 4, "Saddles:
/// the tie-break").
struct TieBreakUpdate {
  TieBreak state;        ///< the state to hold until the next sampling instant
  bool started{false};   ///< a new detour started at this instant
  bool released{false};  ///< the held detour ended at this instant
};

/// The tie-break at a sampling instant t_k of [PET-ERG eq. (5)] (docs/pet-erg.md, section 4,
/// "Saddles: the tie-break"). A held detour is released when its cone's band is no longer active
/// (c_i ≥ ζ_i) or when ρ_nᵀ(σĥ) ≥ kTieBreakRelease ‖ρ_a‖. Otherwise, with none held, a detour
/// starts when ‖ρ_a‖ > `floor` (R_g not at R_d), some band is active, ‖ρ_n‖ ≤ kTieBreakBalance
/// ‖ρ_a‖, around the active cone i with the largest ‖ρ_r,i‖, if ρ_n has no clear component along
/// ĥ_i (|ρ_nᵀĥ_i| ≤ kTieBreakClearTangent ‖ρ_a‖), on the side whose look-ahead (the body axis
/// carried a quarter turn around cone i at constant c_i) meets the lower largest Σ_{j≠i} P_r,j,
/// if the two differ, else on the side with the lower P at R_g exp(±kTieBreakProbe ĥ_i) (ties to
/// 1e-12 relative: +1), and only if P is lower there than at R_g (a saddle, not a minimum of P).
[[nodiscard]] TieBreakUpdate update_tie_break(const TieBreak& held, std::span<const ConeConstraint> cones,
                                              const Mat3& R_g, const Mat3& R_d, double floor) noexcept;

/// The field the reference follows: ρ_n, or with an active detour ρ_n + σ g ‖ρ_a‖ ĥ_i
/// (g = kTieBreakDetourGain) [PET-ERG Sec. III-B.2] (docs/pet-erg.md, section 4, "Saddles: the
/// tie-break"). `rho_n` is ρ_n(R_d, R_g).
[[nodiscard]] Vec3 tie_break_field(const TieBreak& tie, std::span<const ConeConstraint> cones,
                                   const Mat3& R_g, const Mat3& R_d, const Vec3& rho_n) noexcept;

}  // namespace attiguard::governor
