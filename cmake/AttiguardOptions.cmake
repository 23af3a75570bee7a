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
if(ATTIGUARD_SANITIZE)
  target_compile_options(attiguard_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(attiguard_options INTERFACE -fsanitize=address,undefined)
endif()
