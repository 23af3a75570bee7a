/// @file viewer_bundle.cpp
/// The viewer bundle embedded with the assembler's .incbin (docs/viewer.md, "The bundle"): the
/// file ATTIGUARD_VIEWER_BUNDLE_FILE (viewer/dist/attiguard_viewer.js) becomes read-only data
/// between two symbols of this object file; src/CMakeLists.txt makes this object depend on it.

#include "attiguard/cli/viewer_bundle.hpp"

#ifndef ATTIGUARD_VIEWER_BUNDLE_FILE
#error "ATTIGUARD_VIEWER_BUNDLE_FILE (the path of viewer/dist/attiguard_viewer.js) is not defined"
#endif

// The bytes of the file, then its end; hidden symbols, so that nothing outside the program
// sees them.
asm(".section .rodata\n"
    ".global attiguard_viewer_bundle_begin\n"
    ".hidden attiguard_viewer_bundle_begin\n"
    ".global attiguard_viewer_bundle_end\n"
    ".hidden attiguard_viewer_bundle_end\n"
    "attiguard_viewer_bundle_begin:\n"
    ".incbin \"" ATTIGUARD_VIEWER_BUNDLE_FILE "\"\n"
    "attiguard_viewer_bundle_end:\n"
    ".byte 0\n"
    ".previous\n");

extern "C" const char attiguard_viewer_bundle_begin[];
extern "C" const char attiguard_viewer_bundle_end[];

namespace attiguard::cli {

std::string_view embedded_viewer_bundle() noexcept {
  return {attiguard_viewer_bundle_begin,
          static_cast<std::string_view::size_type>(attiguard_viewer_bundle_end -
                                                   attiguard_viewer_bundle_begin)};
}

}  // namespace attiguard::cli
