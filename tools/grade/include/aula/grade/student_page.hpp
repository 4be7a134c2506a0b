#pragma once
// What a student's own run page may carry (`runs/<student>/<world>-seed<k>.html`, the page the
// teacher hands to that student): only what is theirs. The run's report and trace hold text the
// student's code wrote (an exception's message, a crash's line) and the teacher's paths (the
// world's file, the out folder, a calibration). A student's code can read its run's world, which
// may be a held-out one, and put it in an exception's message. So, before the page is made, every
// string of the report and of the trace is:
// - withheld when it quotes any of the run's world files (kQuoteBytes bytes or more in a row of
//   the world or a model it includes): "(withheld: it quotes the run's world)";
// - shortened to kStudentTextChars characters (the student's own output, capped);
// - stripped of the teacher's folders: an absolute path is left as its file's name.
// The referee's still picture, which writes the algorithm's failure in full, is left out when that
// text is changed by the rules above.
// The teacher's report.html keeps everything as it was.

#include <aula/grade/run_page.hpp>

#include <map>
#include <string>
#include <vector>

namespace aula::grade {

constexpr size_t kQuoteBytes = 32;
constexpr size_t kStudentTextChars = 500;

// The texts each run's page must not quote: its world file and the files that includes, for the
// runs of OUT/manifest.json (its runs' --world=), each world read once. A run not in it (no
// manifest, a world no longer readable) has none: paths and caps still apply.
class WorldTexts {
 public:
  explicit WorldTexts(const std::string& out_dir);
  // Of the run whose result's "log" is `log`.
  const std::vector<std::string>& ofRun(const std::string& log) const;

 private:
  std::map<std::string, std::vector<std::string>> texts_;  // by world path
  std::map<std::string, std::string> world_of_log_;
};

// One string as a student's page may show it.
std::string forTheStudent(const std::string& text, const std::vector<std::string>& withheld);

// A run's files as its student's page may show them (report and trace; the picture is the referee's).
RunFiles forTheStudent(RunFiles run, const std::vector<std::string>& withheld);

}  // namespace aula::grade
