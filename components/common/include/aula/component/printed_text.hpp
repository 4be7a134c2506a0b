#pragma once
// What the student's program printed, kept for the window's console: the last kKeepBytes (from a
// line's start), and how much was ever printed, so that a reader who remembers where it stopped
// gets only what is new, and says so when the text it missed is gone. One owner writes
// (AlgorithmHostBase::takePrinted, after each tick), readers only read: no shared cursor.

#include <cstdint>
#include <string>

namespace aula::component {

class PrintedText {
 public:
  static constexpr size_t kKeepBytes = 64 * 1024;

  void append(const std::string& text) {
    if (text.empty()) return;
    kept_ += text;
    total_ += text.size();
    if (kept_.size() > 2 * kKeepBytes) {  // trimmed now and then, so a print costs the same all run
      size_t cut = kept_.size() - kKeepBytes;
      const size_t line = kept_.find('\n', cut);
      kept_.erase(0, line == std::string::npos ? cut : line + 1);
    }
  }
  // What was printed since `position` (the total a reader had seen), which becomes the total now.
  std::string since(uint64_t& position) const {
    const uint64_t first_kept = total_ - kept_.size();
    std::string out;
    if (position < first_kept) {
      out = "[... " + std::to_string(first_kept - position) + " bytes printed meanwhile are no longer kept]\n";
      position = first_kept;
    }
    out += kept_.substr(static_cast<size_t>(position - first_kept));
    position = total_;
    return out;
  }
  uint64_t total() const { return total_; }

 private:
  std::string kept_;
  uint64_t total_ = 0;
};

}  // namespace aula::component
