#include "input/prm_statements.h"

#include "input/input_error.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>

namespace penny
{
  namespace
  {
    // The first word of a line, as written.
    std::string first_word(const std::string &line)
    {
      const std::size_t start = line.find_first_not_of(" \t\r");
      return start == std::string::npos ? "" : line.substr(start, line.find_first_of(" \t\r", start) - start);
    }

    std::string upper_case(std::string word)
    {
      std::transform(word.begin(), word.end(), word.begin(),
                     [](const unsigned char ch) { return std::toupper(ch); });
      return word;
    }

    std::string lower_case(std::string word)
    {
      std::transform(word.begin(), word.end(), word.begin(),
                     [](const unsigned char ch) { return std::tolower(ch); });
      return word;
    }

    // One statement of a .prm file: its keyword as written (set, subsection,
    // end or include, in some case) and the rest of the line.
    std::pair<std::string, std::string> statement(const std::string &line)
    {
      const std::string trimmed = dealii::Utilities::trim(line);
      const std::string word    = first_word(trimmed);
      return {word, dealii::Utilities::trim(trimmed.substr(word.size()))};
    }

    class StatementScan
    {
    public:
      void scan(const std::string &filename)
      {
        const std::string file = std::filesystem::weakly_canonical(filename).string();
        if (std::find(open_files.begin(), open_files.end(), file) != open_files.end())
          throw InputError("parameter file " + in_quotes(filename) +
                           " includes itself (a cycle of include statements)");
        if (open_files.size() == 16)
          throw InputError("parameter file " + in_quotes(filename) +
                           ": include statements nest deeper than 16 files");
        // A FIFO, a device or a folder would hang, spin or read as empty.
        if (!std::filesystem::is_regular_file(filename))
          throw InputError("parameter file " + in_quotes(filename) + " does not exist or is not a file");
        std::ifstream in(filename);
        if (!in)
          throw InputError("parameter file " + in_quotes(filename) + " cannot be read");
        open_files.push_back(file);
        result.files.push_back(filename);
        std::string  line;
        unsigned int number = 0;
        // Each file balances its own subsections, as deal.II's reader requires.
        const std::size_t outer = path.size();
        // Lines of an included file name the file.
        const auto line_at = [&](const unsigned int n) {
          return (open_files.size() > 1 ? in_quotes(filename) + ", " : "") + "line " + std::to_string(n);
        };
        while (std::getline(in, line))
          {
            const unsigned int first = ++number;
            // deal.II's reader takes the mark for text before the statement.
            if (first == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
              throw InputError("parameter file " + in_quotes(filename) +
                               " starts with a UTF-8 byte-order mark; save it without one (plain UTF-8 or "
                               "ASCII)");
            // As deal.II's reader: each line trimmed; while one ends in a
            // backslash, the next (trimmed) line is joined to it without it;
            // then the comment goes.
            line           = dealii::Utilities::trim(line);
            bool continues = !line.empty() && line.back() == '\\';
            if (continues)
              line.pop_back();
            for (std::string next; continues && std::getline(in, next); ++number)
              {
                if (line.find('#') != std::string::npos)
                  throw InputError(line_at(number) +
                                   ": a comment ends in '\\', which would join the next line to the comment");
                next      = dealii::Utilities::trim(next);
                continues = !next.empty() && next.back() == '\\';
                if (continues)
                  next.pop_back();
                line += next;
              }
            const std::string where = line_at(first);
            // deal.II's reader and every message would end the text there.
            if (line.find('\0') != std::string::npos)
              throw InputError(where + ": a NUL byte; a .prm file is text");
            const std::size_t comment = line.find('#');
            // deal.II's reader has no escape: the value would end in the backslash.
            if (comment != std::string::npos && comment > 0 && line[comment - 1] == '\\')
              throw InputError(where +
                               ": '\\#' does not escape '#' in a .prm file, where '#' always starts a "
                               "comment (a .json or .xml parameter file takes any character)");
            if (comment != std::string::npos)
              line.erase(comment);
            std::replace(line.begin(), line.end(), '\t', ' ');
            const auto [word, rest]   = statement(line);
            const std::string keyword = lower_case(word);
            result.sets_any           = result.sets_any || !keyword.empty();
            if (!keyword.empty() && keyword != "set" && keyword != "subsection" && keyword != "end" &&
                keyword != "include")
              throw InputError(where + ": " + in_quotes(word) +
                               " starts no statement (a line is set, subsection, end, include or a comment)");
            if (!keyword.empty() && word != keyword && word != upper_case(keyword))
              throw InputError(where + ": " + in_quotes(word) +
                               ": a keyword is all lower or all upper case (" + keyword + " or " +
                               upper_case(keyword) + ")");
            if (keyword == "end" && !rest.empty())
              throw InputError(where + ": 'end' takes nothing after it");
            if (keyword == "include" && rest.empty())
              throw InputError(where + ": 'include' without a file name");
            if (keyword == "subsection" && rest.empty())
              throw InputError(where + ": 'subsection' without a name");
            if (keyword == "subsection")
              {
                path.push_back(rest);
                opened_at.push_back(where);
              }
            else if (keyword == "end" && path.size() == outer)
              throw InputError(where + ": 'end' without a subsection to end" +
                               (outer > 0 ? " in this file" : ""));
            else if (keyword == "end")
              {
                path.pop_back();
                opened_at.pop_back();
              }
            else if (keyword == "include")
              include(rest, filename, where);
            else if (keyword == "set" && rest.find('=') != std::string::npos)
              {
                std::string entry;
                for (const std::string &subsection : path)
                  entry += subsection + "/";
                const std::string name = dealii::Utilities::trim(rest.substr(0, rest.find('=')));
                entry += name;
                result.set_statements[{file, first}] = {where, entry};
                const auto [earlier, first_time] =
                    set_at.emplace(entry, std::make_pair(filename, "line " + std::to_string(first)));
                const auto &[earlier_file, earlier_line] = earlier->second;
                if (!first_time)
                  throw InputError(where + ": " + entry + " is set a second time (first on " +
                                   (earlier_file == filename ? "" : in_quotes(earlier_file) + ", ") +
                                   earlier_line + "); set each entry once");
                if (path.empty() && name == "Scene")
                  result.scene = dealii::Utilities::trim(rest.substr(rest.find('=') + 1));
              }
          }
        if (path.size() > outer)
          throw InputError(opened_at.back() + ": subsection " + in_quotes(path.back()) + " has no 'end'" +
                           (open_files.size() > 1 ? " in its file" : ""));
        open_files.pop_back();
      }

      PrmStatements result;

    private:
      // deal.II's reader opens an included file from the working folder, not
      // from the including file's: a name that exists only beside the
      // including file gets a hint.
      void include(const std::string &included, const std::string &including, const std::string &where)
      {
        namespace fs          = std::filesystem;
        const fs::path beside = fs::path(including).parent_path() / included;
        if (!fs::exists(included) && fs::path(included).is_relative() && fs::is_regular_file(beside))
          throw InputError(where + ": include " + in_quotes(included) +
                           " does not exist in the working folder, which include statements start from; it "
                           "exists beside the including file (include " +
                           in_quotes(beside.string()) + ", or run from that folder)");
        scan(included);
      }

      std::vector<std::string> open_files; // the chain of includes being read
      std::vector<std::string> path;       // subsections entered
      std::vector<std::string> opened_at;  // where each was entered: "line N"
      std::map<std::string, std::pair<std::string, std::string>>
          set_at; // entry -> (file, "line N") setting it
    };
  } // namespace

  PrmStatements scan_prm_statements(const std::string &filename)
  {
    StatementScan scan;
    scan.scan(filename);
    return scan.result;
  }
} // namespace penny
