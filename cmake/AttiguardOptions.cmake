# Project-wide compile options, applied to attiguard's own targets only (not to dependencies).
add_library(attiguard_options INTERFACE)
target_compile_options(attiguard_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Werror>)
if(ATTIGUARD_SANITIZE)
  target_compile_options(attiguard_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_link_options(attiguard_options INTERFACE -fsanitize=address,undefined)
endif()
