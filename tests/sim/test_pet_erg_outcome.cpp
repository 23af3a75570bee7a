// The outcome of a pet_erg run (docs/pet-erg.md, "Outcomes"): the motion record of R_g and the
// classification rules on synthetic evidence (the end-to-end cases are in test_pet_erg_run.cpp).

#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/pet_erg_outcome.hpp"

namespace attiguard::sim {
namespace {

using lie::Mat3;
using lie::Vec3;

Mat3 about_z(double angle) { return lie::exp(Vec3(0.0, 0.0, angle)); }

TEST(ReferenceMotion, CountsMovesAndReversalsFromTheWindowStartOnly) {
  ReferenceMotion m(1.0);
  m.observe(0.0, about_z(5.0));  // before the window: ignored
  m.observe(0.5, about_z(-5.0));
  m.observe(1.0, about_z(0.0));
  m.observe(1.1, about_z(0.1));   // +0.1
  m.observe(1.2, about_z(0.2));   // +0.1
  m.observe(1.3, about_z(0.15));  // −0.05: reversal
  m.observe(1.4, about_z(0.15));  // no move
  m.observe(1.5, about_z(0.25));  // +0.1: reversal with respect to the last move
  EXPECT_EQ(m.moves(), 4);
  EXPECT_EQ(m.reversals(), 2);
  EXPECT_NEAR(m.displacement(), 0.25, 1e-12);
  EXPECT_NEAR(m.largest_move(), 0.1, 1e-12);
  EXPECT_NEAR(m.path_length(), 0.35, 1e-12);
}

TEST(ReferenceMotion, MovesBelowTheFloorAreRest) {
  ReferenceMotion m(0.0);
  for (int k = 0; k < 100; ++k) m.observe(k, about_z((k % 2 == 0 ? 1.0 : -1.0) * 1e-11));
  EXPECT_EQ(m.moves(), 0);
  EXPECT_EQ(m.reversals(), 0);
}

OutcomeEvidence evidence(double convergence_time, double left, const ReferenceMotion& m) {
  OutcomeEvidence e;
  e.convergence_time = convergence_time;
  e.distance_left = left;
  e.distance_tolerance = 0.0141;
  e.last_half = m;
  return e;
}

TEST(PetErgOutcome, EachRuleAndItsPrecedence) {
  ReferenceMotion at_rest(0.0);
  at_rest.observe(0.0, about_z(1.0));
  at_rest.observe(1.0, about_z(1.0));
  ReferenceMotion moving(0.0);
  for (int k = 0; k <= 10; ++k) moving.observe(k, about_z(0.02 * k));
  ReferenceMotion chatter(0.0);
  for (int k = 0; k <= 40; ++k) chatter.observe(k, about_z(k % 2 == 0 ? 0.0 : 0.018));

  EXPECT_EQ(classify_outcome(evidence(12.0, 0.0, chatter)), PetErgOutcome::converged);
  EXPECT_EQ(classify_outcome(evidence(-1.0, 0.01, chatter)), PetErgOutcome::chattering);
  EXPECT_EQ(classify_outcome(evidence(-1.0, 1.25, at_rest)), PetErgOutcome::stalled);
  // A stalled reference that jitters by 1.5e-5 rad is stalled, not chattering.
  ReferenceMotion jitter(0.0);
  for (int k = 0; k <= 40; ++k) jitter.observe(k, about_z(1.0 + (k % 2 == 0 ? 0.0 : 1.5e-5)));
  EXPECT_EQ(classify_outcome(evidence(-1.0, 1.25, jitter)), PetErgOutcome::stalled);
  // Moving 0.2 rad over the last half with 1.25 rad left: not stalled, only slow.
  EXPECT_EQ(classify_outcome(evidence(-1.0, 1.25, moving)), PetErgOutcome::not_converged_by_end);
  // At R_d (within the distance tolerance) but the attitude has not settled: not stalled.
  EXPECT_EQ(classify_outcome(evidence(-1.0, 0.001, at_rest)), PetErgOutcome::not_converged_by_end);
  OutcomeEvidence ungoverned = evidence(-1.0, 1.25, at_rest);
  ungoverned.governed = false;
  EXPECT_EQ(classify_outcome(ungoverned), PetErgOutcome::not_converged_by_end);
}

TEST(PetErgOutcome, NamesAreTheSummaryValues) {
  EXPECT_EQ(kPetErgOutcomeNames.name(PetErgOutcome::converged), "converged");
  EXPECT_EQ(kPetErgOutcomeNames.name(PetErgOutcome::stalled), "stalled");
  EXPECT_EQ(kPetErgOutcomeNames.name(PetErgOutcome::not_converged_by_end), "not_converged_by_end");
  EXPECT_EQ(kPetErgOutcomeNames.name(PetErgOutcome::chattering), "chattering");
}

}  // namespace
}  // namespace attiguard::sim
