# ctest script: `attiguard tune` in one process (2 threads) and under `mpirun -n 2` (1 and 2
# threads per rank) must find the same `best` and evaluate the same `points` (tune.json beyond
# its rank/thread counts and wall time) and write the same best.toml; a search without a
# converged point exits 4 and a bad [tune] table exits 2 under MPI too, on every rank, without
# hanging, and so does a failure of rank 0 alone (docs/pet-erg.md, section 15). Variables: CLI, MPIEXEC, SOURCE_DIR, WORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(mpi ${MPIEXEC} -n 2 --oversubscribe --allow-run-as-root)
set(scenario ${SOURCE_DIR}/examples/pet_erg_slew170.toml)
set(common --budget 24 --seed 5 --no-plot)

macro(run_expect expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 300)
  if(NOT rc EQUAL ${expected})
    message(FATAL_ERROR "exit ${rc}, expected ${expected}: ${ARGN}\n${out}\n${err}")
  endif()
endmacro()
run_expect(0 ${CLI} tune ${scenario} ${common} --threads 2 --out ${WORK_DIR}/one)
run_expect(0 ${mpi} ${CLI} tune ${scenario} ${common} --out ${WORK_DIR}/mpi)
run_expect(0 ${mpi} ${CLI} tune ${scenario} ${common} --threads 2 --out ${WORK_DIR}/mpi_threads)

file(READ ${WORK_DIR}/one/tune.json reference)
string(JSON ranks GET "${reference}" ranks)
string(JSON evaluated GET "${reference}" evaluated)
if(NOT ranks EQUAL 1 OR NOT evaluated EQUAL 24)
  message(FATAL_ERROR "one/tune.json: ranks ${ranks}, evaluated ${evaluated} (expected 1, 24)")
endif()
foreach(variant mpi mpi_threads)
  file(READ ${WORK_DIR}/${variant}/tune.json other)
  string(JSON other_ranks GET "${other}" ranks)
  if(NOT other_ranks EQUAL 2)
    message(FATAL_ERROR "${variant}/tune.json: ranks ${other_ranks}, expected 2")
  endif()
  foreach(key best points nominal convergence_time)
    string(JSON a GET "${reference}" ${key})
    string(JSON b GET "${other}" ${key})
    string(JSON same EQUAL "${a}" "${b}")
    if(NOT same)
      message(FATAL_ERROR "${variant}/tune.json: '${key}' differs from one process's")
    endif()
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/one/best.toml
                          ${WORK_DIR}/${variant}/best.toml RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "${variant}/best.toml differs from one process's")
  endif()
endforeach()

# No converged point: exit 4 on every rank (each rank holds every point, so all conclude alike).
run_expect(4 ${mpi} ${CLI} tune ${SOURCE_DIR}/tests/data/campaign/pet_erg_stalling.toml --budget 4
           --no-plot --range control.kp=4:6 --range control.kd=0.8:1.2 --out ${WORK_DIR}/none)
file(READ ${WORK_DIR}/none/tune.json none)
string(JSON outcome GET "${none}" outcome)
if(NOT outcome STREQUAL "none_converged")
  message(FATAL_ERROR "none/tune.json: outcome ${outcome}, expected none_converged")
endif()
# A failure on rank 0 alone (it alone makes DIR; here DIR is a file): exit 2, the other rank
# does not wait for it in the search's first exchange.
file(WRITE ${WORK_DIR}/a_file "")
run_expect(2 ${mpi} ${CLI} tune ${scenario} ${common} --out ${WORK_DIR}/a_file)
# A bad [tune] table: exit 2 under MPI.
run_expect(2 ${mpi} ${CLI} tune ${SOURCE_DIR}/tests/data/bad_inputs/tune_range_reversed.toml
           --no-plot --out ${WORK_DIR}/bad)
message(STATUS "tune: 1 process x 2 threads, mpirun -n 2 and mpirun -n 2 x 2 threads: same best and points; exit 4 and 2 under MPI")
file(REMOVE_RECURSE ${WORK_DIR})
