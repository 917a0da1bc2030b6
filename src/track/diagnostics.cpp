#include "track/diagnostics.hpp"

#include <algorithm>

namespace trailray::track {

std::string Diagnostic::to_string() const {
  std::string out = file;
  // Appends piecewise: `":" + std::string` trips GCC 12's false -Wrestrict (PR 105329).
  if (position.line > 0) {
    out.append(":").append(std::to_string(position.line));
    if (position.column > 0) out.append(":").append(std::to_string(position.column));
  } else if (position.byte_offset >= 0) {
    out.append(": byte ").append(std::to_string(position.byte_offset));
  }
  out.append(": ").append(message);
  return out;
}

void WarningCollector::add(const std::string& kind, const SourcePosition& where, const std::string& message) {
  auto [it, inserted] = groups_.try_emplace(kind);
  Group& g = it->second;
  if (inserted) {
    g.first = where;
    g.first_message = message;
    g.order = next_order_++;
  }
  ++g.count;
}

void WarningCollector::add_single(const SourcePosition& where, const std::string& message) {
  singles_.push_back(Diagnostic{file_, where, message});
}

void WarningCollector::merge(const WarningCollector& later,
                             const std::function<SourcePosition(SourcePosition)>& shift) {
  std::vector<std::pair<std::size_t, const std::string*>> kinds;
  for (const auto& [kind, g] : later.groups_) kinds.emplace_back(g.order, &kind);
  std::sort(kinds.begin(), kinds.end());
  for (const auto& [order, kind] : kinds) {
    const Group& g = later.groups_.at(*kind);
    auto [it, inserted] = groups_.try_emplace(*kind);
    if (inserted) {
      it->second = g;
      it->second.first = shift(g.first);
      it->second.order = next_order_++;
    } else {
      it->second.count += g.count;
    }
  }
  for (Diagnostic d : later.singles_) {
    d.position = shift(d.position);
    singles_.push_back(std::move(d));
  }
}

std::size_t WarningCollector::total() const {
  std::size_t n = singles_.size();
  for (const auto& [kind, g] : groups_) n += g.count;
  return n;
}

std::vector<Diagnostic> WarningCollector::diagnostics() const {
  std::vector<std::pair<std::size_t, Diagnostic>> ordered;
  for (const auto& [kind, g] : groups_) {
    std::string msg = g.first_message;
    if (g.count > 1) msg += " (" + std::to_string(g.count) + " times in all; first shown)";
    ordered.emplace_back(g.order, Diagnostic{file_, g.first, msg});
  }
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Diagnostic> out = singles_;
  for (auto& [order, d] : ordered) out.push_back(std::move(d));
  return out;
}

}  // namespace trailray::track
