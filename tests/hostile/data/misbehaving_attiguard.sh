#!/usr/bin/env bash
# A stand-in for attiguard that misbehaves on purpose, for run_hostile.py's self-test
# (tests/hostile/selftest_cases.toml): each argument names one fault the runner must catch.
case "$1" in
  nan) mkdir -p out && printf 't,q_w\n0,1\n1,nan\n' > out/trajectory.csv ;;
  two-lines) echo "attiguard: error: s.toml:1:1: one" >&2
             echo "attiguard: error: s.toml:2:1: two" >&2; exit 2 ;;
  abort) kill -ABRT $$ ;;
  hang) exec sleep 600 ;;
esac
