// What deal.II's reader of .prm files does not check: it follows `include
// FILE` without end, and lets the last of two `set` statements of one entry
// win silently. This scan reads the statements of a .prm file and of the files
// it includes, refuses a cycle of includes and an entry set twice (naming the
// lines), and finds the 'Scene' entry, which decides what else is declared.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace penny
{
  struct PrmStatements
  {
    std::vector<std::string>   files; // the file and every file it includes, in reading order
    bool                       sets_any = false;
    std::optional<std::string> scene; // 'set Scene = ...' at the top level, if set
    // Each set statement by (canonical file, line): where it is, as messages
    // name it ("line 8", or "'inc.prm', line 3"), and its entry "Subsection/Name".
    std::map<std::pair<std::string, unsigned int>, std::pair<std::string, std::string>> set_statements;
  };

  // Throws InputError (one line) for a file that is missing or not a regular
  // file, starts with a byte-order mark, a cycle of includes, includes nested
  // deeper than 16 files, and an entry set twice.
  PrmStatements scan_prm_statements(const std::string &filename);
} // namespace penny
