# ctest script: `attiguard reach` on a partitioned initial set, run in one thread, in two threads
# and under `mpirun -n 2`, must write the same files byte for byte (reach.json up to its
# wall-clock times), and a set that cannot be proved must exit 4 on every split.
# Variables: CLI, MPIEXEC, SOURCE_DIR, WORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(mpi ${MPIEXEC} -n 2 --oversubscribe --allow-run-as-root)

# The example's [partition] table is its last one: append the thread count to it.
# A shorter horizon (4 of its 10 steps) and 200 soundness samples: the same partitioned, threaded
# and MPI paths in a third of the example's time.
file(READ ${SOURCE_DIR}/examples/conreach_hold_partitioned.toml text)
foreach(key_value "horizon = 0.5;horizon = 0.2" "steps = 10;steps = 4" "samples = 2000;samples = 200")
  list(GET key_value 0 from)
  list(GET key_value 1 to)
  string(REGEX MATCH "\n${from}[ \n]" found "${text}")
  if(NOT found)
    message(FATAL_ERROR "mpi_equal.cmake: the example no longer has the line '${from}'")
  endif()
  string(REGEX REPLACE "\n${from}([ \n])" "\n${to}\\1" text "${text}")
endforeach()
foreach(threads 1 2)
  file(WRITE ${WORK_DIR}/threads${threads}.toml "${text}threads = ${threads}\n")
endforeach()

macro(run_expect expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL ${expected})
    message(FATAL_ERROR "exit ${rc}, expected ${expected}: ${ARGN}\n${out}\n${err}")
  endif()
endmacro()
run_expect(0 ${CLI} reach ${WORK_DIR}/threads1.toml --out ${WORK_DIR}/serial)
run_expect(0 ${CLI} reach ${WORK_DIR}/threads2.toml --out ${WORK_DIR}/threads)
run_expect(0 ${mpi} ${CLI} reach ${WORK_DIR}/threads1.toml --out ${WORK_DIR}/mpi)

# reach.json without its wall-clock times (top level, soundness, adversarial, partition, each
# cell of "final").
function(read_without_times path out_var)
  file(READ ${path} j)
  string(JSON j REMOVE "${j}" wall_time_s)
  string(JSON j REMOVE "${j}" soundness wall_time_s)
  string(JSON j ERROR_VARIABLE no_adversarial REMOVE "${j}" adversarial wall_time_s)
  string(JSON j ERROR_VARIABLE no_partition REMOVE "${j}" partition wall_time_s)
  string(JSON cells LENGTH "${j}" final)
  math(EXPR last "${cells} - 1")
  foreach(i RANGE ${last})
    string(JSON j REMOVE "${j}" final ${i} wall_time_s)
  endforeach()
  set(${out_var} "${j}" PARENT_SCOPE)
endfunction()

read_without_times(${WORK_DIR}/serial/reach.json reference)
string(JSON cells GET "${reference}" cells)
if(cells LESS 2)
  message(FATAL_ERROR "the example must be partitioned (cells = ${cells})")
endif()
foreach(variant threads mpi)
  foreach(f steps.csv tube.csv boundary.csv trajectory.csv samples.csv)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/serial/${f}
                            ${WORK_DIR}/${variant}/${f} RESULT_VARIABLE diff)
    if(NOT diff EQUAL 0)
      message(FATAL_ERROR "${variant}/${f} differs from serial/${f}")
    endif()
  endforeach()
  read_without_times(${WORK_DIR}/${variant}/reach.json other)
  string(JSON same EQUAL "${reference}" "${other}")
  if(NOT same)
    message(FATAL_ERROR "${variant}/reach.json differs from serial/reach.json (beyond wall times)")
  endif()
endforeach()

# A set too large to prove: exit 4 under MPI too (every rank reaches the same verdict).
run_expect(4 ${mpi} ${CLI} reach ${SOURCE_DIR}/examples/conreach_hold_too_large.toml
           --out ${WORK_DIR}/too_large)
message(STATUS "reach: 1 thread, 2 threads and mpirun -n 2 identical (${cells} cells); failing set exits 4")
file(REMOVE_RECURSE ${WORK_DIR})
