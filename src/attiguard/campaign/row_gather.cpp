#include "attiguard/campaign/row_gather.hpp"

#include <cstdlib>

namespace attiguard::campaign {

namespace {

/// Serialises rows as "index\tline\n" (lines never contain tabs or newlines).
std::string pack(const std::map<long, std::string>& rows) {
  std::string s;
  for (const auto& [index, line] : rows) s += std::to_string(index) + '\t' + line + '\n';
  return s;
}

void unpack(const std::string& s, std::map<long, std::string>& rows) {
  std::size_t pos = 0;
  while (pos < s.size()) {
    const std::size_t tab = s.find('\t', pos);
    const std::size_t nl = s.find('\n', tab);
    if (tab == std::string::npos || nl == std::string::npos) break;
    rows[std::atol(s.substr(pos, tab - pos).c_str())] = s.substr(tab + 1, nl - tab - 1);
    pos = nl + 1;
  }
}

}  // namespace

std::map<long, std::string> gather_rows(const std::map<long, std::string>& mine,
                                        const parallel::World& world) {
  if (world.size == 1) return mine;
  std::map<long, std::string> all;
  for (const std::string& part : parallel::gather_bytes(pack(mine), world)) unpack(part, all);
  return all;
}

}  // namespace attiguard::campaign
