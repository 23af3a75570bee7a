/// @file scenario_reader_fuzz.cpp
/// libFuzzer target for the scenario reader: TOML parsing (load path of every scenario), the
/// kind registry and each kind's full validation (check), and campaign [dispersions].
/// Any attiguard::Error is an expected rejection of bad input; anything else (another
/// exception, a crash, a sanitizer report) is a bug.
///   cmake -S . -B build-fuzz -DATTIGUARD_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++
///   build-fuzz/fuzz/scenario_reader_fuzz -max_total_time=60 build-fuzz/corpus

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "attiguard/app/kinds.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const attiguard::scenario::Document doc =
        attiguard::scenario::parse_document(text, "fuzz.toml");
    if (doc.has_top_level("dispersions")) {
      (void)attiguard::scenario::read_dispersions(doc);
      const auto nominal = attiguard::scenario::nominal_document(doc);
      attiguard::app::handler_for(nominal).check(nominal);
    } else {
      attiguard::app::handler_for(doc).check(doc);
    }
  } catch (const attiguard::Error&) {
    // invalid input, reported with a located message: expected
  }
  return 0;
}
