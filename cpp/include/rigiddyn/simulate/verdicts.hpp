// The verdicts of an estimate's records: "reliable" (reliable_verdict) or the reason the record's estimate is not.
//
// A run's records repeat a few texts (where every step is recorded, three records in four read "interpolated
// between the reliable records before and after it"), so each record holds an index into the run's distinct
// texts: a record costs 4 bytes and no allocation, and a consumer converts each distinct text once (the Python
// GlobalError makes one str per text, shared by its records).
#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rigiddyn {

// The verdict of a record whose estimate is trusted.
inline constexpr std::string_view reliable_verdict = "reliable";

// Whether a record's verdict is reliable_verdict (its size compared first: a test per record, inline).
inline bool is_reliable(std::string_view verdict) { return verdict == reliable_verdict; }

class Verdicts {
 public:
  Verdicts() = default;
  Verdicts(std::initializer_list<std::string_view> verdicts);

  std::size_t size() const { return text_of_record_.size(); }
  bool empty() const { return text_of_record_.empty(); }
  // Record i's verdict.
  const std::string& operator[](std::size_t i) const { return texts_[text_of_record_[i]]; }

  void reserve(std::size_t n) { text_of_record_.reserve(n); }
  // Appends a record whose verdict is `verdict`.
  void push_back(std::string_view verdict) { text_of_record_.push_back(add_text(verdict)); }
  // Record i's verdict becomes `verdict`.
  void set(std::size_t i, std::string_view verdict) { text_of_record_[i] = add_text(verdict); }
  // n records, each with the verdict `verdict`.
  void assign(std::size_t n, std::string_view verdict);
  // Drops every record and keeps the texts with their indices (for records that index another table's texts).
  void clear_records() { text_of_record_.clear(); }

  // The distinct texts (in the order of their first use; a text replaced by set may no longer be used), and
  // record i's index into them.
  const std::vector<std::string>& texts() const { return texts_; }
  std::uint32_t text_index(std::size_t i) const { return text_of_record_[i]; }

  // The index of `verdict` in texts(), added if new: the text of the previous call is compared first (records
  // come in runs of one verdict), then an ordered index of the texts.
  std::uint32_t add_text(std::string_view verdict);
  // Appends a record whose verdict is texts()[k] (k from add_text); std::out_of_range for a k that is no text's.
  void push_back_text(std::uint32_t k) { text_of_record_.push_back(checked_text(k)); }
  // Record i's verdict becomes texts()[k] (k from add_text); std::out_of_range for a k that is no text's.
  void set_text(std::size_t i, std::uint32_t k) { text_of_record_[i] = checked_text(k); }

 private:
  // (inlined at every record: the throw is out of line)
  std::uint32_t checked_text(std::uint32_t k) const {
    if (k >= texts_.size()) throw_no_text(k);
    return k;
  }
  [[noreturn]] static void throw_no_text(std::uint32_t k);

  std::vector<std::string> texts_;
  std::map<std::string, std::uint32_t, std::less<>> index_of_text_;
  std::vector<std::uint32_t> text_of_record_;
  std::uint32_t last_added_ = 0;  // the index add_text returned last
};

}  // namespace rigiddyn
