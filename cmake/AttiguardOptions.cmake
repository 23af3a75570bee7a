# Project-wide compile options, applied to attiguard's own targets only (not to dependencies).
add_library(attiguard_options INTERFACE)
target_compile_options(attiguard_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Werror>)

# attiguard_glue_optimisation(<target>): Release builds of the target at -O2 rather than CMake's
# -O3 (a target option comes after CMAKE_CXX_FLAGS_RELEASE, so it wins). For the code that
# parses, writes files and drives runs, not for the numerics: the flight-loop layers, sim/ and
# reach/ stay at -O3, where -O2 costs run time (docs/performance.md, "Build"). The results are the
# same either way (no -ffast-math; ExampleFigures compares every figure).
function(attiguard_glue_optimisation target)
  target_compile_options(${target} PRIVATE
    $<$<AND:$<CONFIG:Release>,$<CXX_COMPILER_ID:GNU,Clang>>:-O2>)
endfunction()
# attiguard_test_optimisation(<target>): the test programs' own code at -O1 in the optimised
# configurations (Release; RelWithDebInfo, the sanitizer build of .ci/run), after the configuration's
# level so it wins. The numerics they call are the library's, at its own levels; -O1 compiles
# the tests in 38 % less time than -O2 with GCC and 25 % less with clang's ASan/UBSan build
# (docs/performance.md, "CI of stop 61").
function(attiguard_test_optimisation target)
  target_compile_options(${target} PRIVATE
    $<$<AND:$<CONFIG:Release,RelWithDebInfo>,$<CXX_COMPILER_ID:GNU,Clang>>:-O1>)
endfunction()
if(ATTIGUARD_SANITIZE)
  target_compile_options(attiguard_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(attiguard_options INTERFACE -fsanitize=address,undefined)
endif()
