#include "rigiddyn/simulate/verdicts.hpp"

namespace rigiddyn {

Verdicts::Verdicts(std::initializer_list<std::string_view> verdicts) {
  reserve(verdicts.size());
  for (std::string_view v : verdicts) push_back(v);
}

void Verdicts::assign(std::size_t n, std::string_view verdict) {
  const std::uint32_t k = add_text(verdict);
  text_of_record_.assign(n, k);
}

void Verdicts::throw_no_text(std::uint32_t k) { throw std::out_of_range("Verdicts: no text " + std::to_string(k)); }

std::uint32_t Verdicts::add_text(std::string_view verdict) {
  if (!texts_.empty() && texts_[last_added_] == verdict) return last_added_;
  const auto found = index_of_text_.find(verdict);
  if (found != index_of_text_.end()) return last_added_ = found->second;
  last_added_ = static_cast<std::uint32_t>(texts_.size());
  texts_.emplace_back(verdict);
  index_of_text_.emplace(texts_.back(), last_added_);
  return last_added_;
}

}  // namespace rigiddyn
