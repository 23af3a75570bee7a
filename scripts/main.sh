#!/usr/bin/env bash
# Installs what the main job needs (scripts/setup.sh: compiler, CMake, the library's
# dependencies, Python with numpy and matplotlib; no test tools), builds only the `attiguard`
# program and the Python module (no tests, no benchmarks: scripts/test.sh builds those), and runs
# the main job: the three paper scenarios (PET-ERG, waypoint guidance, ConReach), the
# hold-interval certificate, the constrained waypoint mission and the Python figure, with
# summaries and figures in out/ and an index page out/index.md to open first.
# Prints the time of each part (set-up, build, scenarios: two at a time, one per core).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

part_start=$SECONDS
# Prints "main.sh: PART took N s" and restarts the clock.
part_done() {
  echo "main.sh: $1 took $((SECONDS - part_start)) s"
  part_start=$SECONDS
}

bash scripts/setup.sh main
part_done "set-up (scripts/setup.sh main)"
bash scripts/build.sh -DATTIGUARD_BUILD_TESTS=OFF -DATTIGUARD_BUILD_BENCH=OFF
part_done "build (attiguard and the Python module)"

cli=build/src/attiguard
out=out
mkdir -p "$out"

# scenario NAME ARGS...: `attiguard ARGS` with its stdout and stderr into out/NAME.log; prints
# the log and fails when the command does.
scenario() {
  local name=$1
  shift
  if ! "$cli" "$@" > "$out/$name.log" 2>&1; then
    cat "$out/$name.log" >&2
    echo "main.sh: attiguard $* failed" >&2
    return 1
  fi
}
# Two lanes side by side (two cores), each a few seconds of scenarios and their figures.
lane_papers() {
  # The three paper scenarios.
  scenario pet_erg_paper run examples/pet_erg_paper.toml --out "$out/pet_erg_paper" --plot
  scenario waypoint_paper run examples/waypoint_paper.toml --out "$out/waypoint_paper" --plot
  scenario conreach_paper reach examples/conreach_paper.toml --out "$out/conreach_paper" --plot
}
lane_systems() {
  # The first example of the README (rigid body under the PD law).
  scenario rigid_body_pd run examples/rigid_body_pd.toml --out "$out/rigid_body_pd" --plot
  # The systems together: the PET-ERG's hold interval certified by ConReach, and the waypoint
  # mission through the PET-ERG (skipped when this build has no `mission` kind).
  scenario conreach_hold_certificate reach examples/conreach_hold_certificate.toml \
    --out "$out/conreach_hold_certificate" --plot
  if "$cli" check examples/mission_sun_constrained.toml > /dev/null 2>&1; then
    scenario mission_sun_constrained run examples/mission_sun_constrained.toml \
      --out "$out/mission_sun_constrained" --plot
  fi
}
names=(rigid_body_pd pet_erg_paper waypoint_paper conreach_paper conreach_hold_certificate
       mission_sun_constrained)
for name in "${names[@]}"; do rm -f "$out/$name.log"; done
lane_papers &
papers=$!
lane_systems &
systems=$!
failed=0
wait "$papers" || failed=1
wait "$systems" || failed=1
((failed == 0)) || exit 1
# Their stdout (the one-line outcome and the files written), in a fixed order.
for name in "${names[@]}"; do
  if [[ -f "$out/$name.log" ]]; then
    echo "== $name"
    cat "$out/$name.log"
  fi
done

# A paper figure from the Python package (docs/python.md).
if [[ -f build/python/attiguard/__init__.py ]]; then
  PYTHONPATH="$(pwd)/build/python" /usr/bin/python3 examples/python_pet_erg_figure.py "$out/python"
fi

/usr/bin/python3 scripts/results_index.py "$out" \
  "mission_sun_constrained|Constrained waypoint mission (star tracker kept out of the Sun)|attiguard run examples/mission_sun_constrained.toml --out out/mission_sun_constrained --plot|docs/mission.md" \
  "pet_erg_paper|PET-ERG paper, Sec. V: constrained attitude slew|attiguard run examples/pet_erg_paper.toml --out out/pet_erg_paper --plot|docs/pet-erg.md" \
  "waypoint_paper|Waypoint paper, Sec. VI: single-main-engine waypoint tracking|attiguard run examples/waypoint_paper.toml --out out/waypoint_paper --plot|docs/waypoint.md" \
  "conreach_paper|ConReach paper, Sec. 6: reachable sets on SO(3)xR3|attiguard reach examples/conreach_paper.toml --out out/conreach_paper --plot|docs/reach.md" \
  "conreach_hold_certificate|Hold-interval certificate of the PET-ERG (ConReach, verdict safe)|attiguard reach examples/conreach_hold_certificate.toml --out out/conreach_hold_certificate --plot|docs/mission.md" \
  "python|PET-ERG paper Fig. 4 from Python|PYTHONPATH=build/python /usr/bin/python3 examples/python_pet_erg_figure.py out/python|docs/python.md" \
  "rigid_body_pd|Rigid body under the PD law (first example)|attiguard run examples/rigid_body_pd.toml --out out/rigid_body_pd --plot|docs/scenario-format.md"

part_done "scenarios"

echo
echo "Results are in $(pwd)/$out/: open $out/index.md first."
