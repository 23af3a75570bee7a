#include "attiguard/scenario/key_path.hpp"

#include <charconv>

namespace attiguard::scenario {

std::vector<KeyStep> split_key_path(std::string_view path) {
  std::vector<KeyStep> steps;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const std::size_t dot = std::min(path.find('.', pos), path.size());
    std::string_view part = path.substr(pos, dot - pos);
    KeyStep step;
    const std::size_t open = part.find('[');
    if (open != std::string_view::npos) {
      if (!part.ends_with(']') || open == 0) return {};
      const std::string_view digits = part.substr(open + 1, part.size() - open - 2);
      std::size_t i = 0;
      const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), i);
      if (digits.empty() || r.ec != std::errc{} || r.ptr != digits.data() + digits.size()) return {};
      step.index = i;
      part = part.substr(0, open);
    }
    if (part.empty()) return {};
    step.key = std::string(part);
    steps.push_back(std::move(step));
    pos = dot + 1;
  }
  return steps;
}

const toml::node* resolve_key_path(const toml::table& root, std::string_view path) {
  const std::vector<KeyStep> steps = split_key_path(path);
  if (steps.empty()) return nullptr;
  const toml::node* n = &root;
  for (const KeyStep& step : steps) {
    const toml::table* t = n->as_table();
    if (t == nullptr) return nullptr;
    n = t->get(step.key);
    if (n == nullptr) return nullptr;
    if (step.index) {
      const toml::array* a = n->as_array();
      if (a == nullptr || *step.index >= a->size()) return nullptr;
      n = a->get(*step.index);
    }
  }
  return n;
}

}  // namespace attiguard::scenario
