# Installs attiguard into a temporary prefix and builds and runs the downstream project
# tests/consumer against it (CTest tests Consumer.*, tests/CMakeLists.txt; docs/install.md).
#
#   cmake -DMODE=full|flight -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -DCXX=<compiler>
#         [-DBUILD_DIR=<attiguard build>] [-DLAUNCHER=ccache] [-DGENERATOR=<gen>] -P run_consumer.cmake
#
# MODE=full:   `cmake --install BUILD_DIR --prefix WORK_DIR/prefix`; the consumer builds
#              flight_loop (attiguard::flight), full_link and robust_design (attiguard::attiguard;
#              robust_design is run on examples/pet_erg_robust_campaign.toml); full_link is
#              also compiled by hand with `pkg-config --cflags --libs attiguard`.
# MODE=flight: a fresh ATTIGUARD_FLIGHT_ONLY=ON build of SOURCE_DIR in WORK_DIR/build that may not
#              find toml++, nlohmann_json, CLI11, CSDP, LAPACK or MPI, installed into
#              WORK_DIR/prefix; the consumer builds flight_loop, which is also compiled by hand
#              with `pkg-config --cflags --libs attiguard-flight`.
# Every step must succeed and every program must exit 0.
cmake_minimum_required(VERSION 3.25)
foreach(var MODE SOURCE_DIR WORK_DIR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT GENERATOR)
  set(GENERATOR "Unix Makefiles")
endif()

# run(<what> <command>...): runs the command, fails the test with its output when it fails.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}): ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "consumer (${MODE}): ${what}: ok")
  string(STRIP "${out}" out)
  if(out AND what MATCHES "^run ")
    message(STATUS "  ${out}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(common -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX})
if(LAUNCHER)
  list(APPEND common -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()

if(MODE STREQUAL "full")
  if(NOT BUILD_DIR)
    message(FATAL_ERROR "run_consumer.cmake: MODE=full needs -DBUILD_DIR=<attiguard build>")
  endif()
  run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  set(consumer_options -DATTIGUARD_CONSUMER_FULL=ON)
  set(programs flight_loop full_link)
  set(pc_package attiguard)
  set(pc_source full_link.cpp)
elseif(MODE STREQUAL "flight")
  set(no_find "")
  foreach(pkg tomlplusplus nlohmann_json CLI11 CSDP LAPACK MPI GTest benchmark pybind11)
    list(APPEND no_find -DCMAKE_DISABLE_FIND_PACKAGE_${pkg}=ON)
  endforeach()
  # -O1: this build shows what installs and links, not speed; at -O3 it took 59 s of the suite.
  run("configure the flight-only build" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
      ${common} -DATTIGUARD_FLIGHT_ONLY=ON "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" ${no_find})
  run("build the flight-only library" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --parallel 2)
  run("install" ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${prefix})
  foreach(absent include/attiguard/scenario include/attiguard/reach bin/attiguard)
    if(EXISTS ${prefix}/${absent})
      message(FATAL_ERROR "consumer (flight): the flight-only install has ${absent}")
    endif()
  endforeach()
  set(consumer_options -DATTIGUARD_CONSUMER_FULL=OFF)
  set(programs flight_loop)
  set(pc_package attiguard-flight)
  set(pc_source flight_loop.cpp)
else()
  message(FATAL_ERROR "run_consumer.cmake: MODE must be full or flight, not '${MODE}'")
endif()

# MODE=full: the installed program writes a working view.html with the viewer bundle it carries
# (docs/viewer.md, "The bundle"): no node on PATH (no PATH at all), no ATTIGUARD_VIEWER_BUNDLE,
# run from outside the source and build trees.
if(MODE STREQUAL "full")
  set(view_dir ${WORK_DIR}/view_run)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=ATTIGUARD_VIEWER_BUNDLE PATH=/nonexistent
                          ${prefix}/bin/attiguard run ${SOURCE_DIR}/examples/rigid_body_pd.toml
                          --out ${view_dir} --view
                  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${view_dir}/view.html)
    message(FATAL_ERROR "consumer (full): the installed `attiguard run --view` failed (${rc}):\n"
                        "${out}\n${err}")
  endif()
  # The bundle's first 100 characters (file(READ … LIMIT) may return one more than asked).
  file(READ ${SOURCE_DIR}/viewer/dist/attiguard_viewer.js bundle_head LIMIT 200)
  string(SUBSTRING "${bundle_head}" 0 100 bundle_head)
  file(READ ${view_dir}/view.html page)
  string(FIND "${page}" "${bundle_head}" at)
  string(FIND "${page}" "id=\"attiguard-data\"" data_at)
  if(at EQUAL -1 OR data_at EQUAL -1)
    message(FATAL_ERROR "consumer (full): the installed program's view.html lacks the viewer "
                        "bundle or the run's data")
  endif()
  message(STATUS "consumer (full): installed `attiguard run --view` without node: ok")
endif()

set(consumer_src ${CMAKE_CURRENT_LIST_DIR})
run("configure the consumer" ${CMAKE_COMMAND} -S ${consumer_src} -B ${WORK_DIR}/consumer
    ${common} -DCMAKE_PREFIX_PATH=${prefix} ${consumer_options})
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer --parallel 2)
foreach(program IN LISTS programs)
  run("run ${program}" ${WORK_DIR}/consumer/${program})
endforeach()
# MODE=full: the robust governor with wheels from plain values flies the example's figures.
if(MODE STREQUAL "full")
  run("run robust_design" ${WORK_DIR}/consumer/robust_design
      ${SOURCE_DIR}/examples/pet_erg_robust_campaign.toml)
endif()

# The same program built with the flags of the installed pkg-config file.
find_program(PKG_CONFIG pkg-config)
if(NOT PKG_CONFIG)
  message(FATAL_ERROR "consumer (${MODE}): pkg-config not found (Debian package pkg-config)")
endif()
file(GLOB pc_dirs LIST_DIRECTORIES true ${prefix}/lib*/pkgconfig ${prefix}/lib/*/pkgconfig)
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PKG_CONFIG_PATH=${pc_dirs}"
                        ${PKG_CONFIG} --cflags --libs ${pc_package}
                RESULT_VARIABLE rc OUTPUT_VARIABLE pc_flags ERROR_VARIABLE pc_err
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "consumer (${MODE}): pkg-config ${pc_package} failed:\n${pc_err}")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
run("compile ${pc_source} with pkg-config ${pc_package}" ${LAUNCHER} ${CXX} -std=c++20 -O1
    ${consumer_src}/${pc_source} -o ${WORK_DIR}/pc_program ${pc_flags})
run("run the pkg-config build of ${pc_source}" ${WORK_DIR}/pc_program)
