#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace masonry
{
  namespace
  {
    struct Location
    {
      std::string  file;
      unsigned int line = 0;
    };

    struct Locations
    {
      std::string                     filename;
      std::map<std::string, Location> entries;
      /** Where each line of the text of read_parameter_text() (the file
       * with its includes inlined) comes from. */
      std::vector<Location> text_lines;
    };

    Locations &
    locations()
    {
      static Locations l;
      return l;
    }

    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r\f\v");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t\r\f\v");
      return s.substr(b, e - b + 1);
    }

    std::string
    collapse_spaces(const std::string &s)
    {
      std::string out;
      bool        space = false;
      for (const char c : s)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += c;
            space = false;
          }
      return out;
    }

    const std::string utf8_bom = "\xEF\xBB\xBF";

    /** Files longer than this are no parameter files (1 GB of text). */
    constexpr std::uintmax_t largest_file = 64u << 20;

    /**
     * The lines of a parameter file (without a UTF-8 byte-order mark), with
     * clear errors for a file that is missing, a directory or too large.
     */
    std::vector<std::string>
    read_lines(const std::string &file, const std::string &include_line)
    {
      const std::string where =
        include_line.empty() ? "" : include_line + ": include of '";
      const std::string after = include_line.empty() ? "" : "'";
      namespace fs            = std::filesystem;
      std::error_code ec;
      AssertThrow(!fs::is_directory(file, ec),
                  dealii::ExcMessage(where + file + after +
                                     ": is a directory, not a parameter file"));
      std::ifstream in(file, std::ios::binary);
      AssertThrow(in.good(),
                  dealii::ExcMessage(where + file + after +
                                     ": cannot open the parameter file"));
      const auto size = fs::file_size(file, ec);
      AssertThrow(ec || size <= largest_file,
                  dealii::ExcMessage(where + file + after + ": is " +
                                     std::to_string(size >> 20) +
                                     " MB long, not a parameter file"));
      std::vector<std::string> lines;
      std::string              line;
      while (std::getline(in, line))
        {
          if (lines.empty() && line.rfind(utf8_bom, 0) == 0)
            line.erase(0, utf8_bom.size());
          lines.push_back(line);
        }
      return lines;
    }

    /** The part of a line before its comment (deal.II: `#`, not `\#`). */
    std::string
    strip_comment(const std::string &line)
    {
      for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
          return line.substr(0, i);
      return line;
    }

    /** `include` or `INCLUDE` followed by white space. */
    bool
    is_include(const std::string &statement)
    {
      return (statement.rfind("include", 0) == 0 ||
              statement.rfind("INCLUDE", 0) == 0) &&
             (statement.size() == 7 ||
              std::isspace(static_cast<unsigned char>(statement[7])));
    }

    bool
    is_set(const std::string &statement)
    {
      return (statement.rfind("set", 0) == 0 ||
              statement.rfind("SET", 0) == 0) &&
             statement.size() > 3 &&
             std::isspace(static_cast<unsigned char>(statement[3]));
    }

    bool
    is_subsection(const std::string &statement)
    {
      return (statement.rfind("subsection", 0) == 0 ||
              statement.rfind("SUBSECTION", 0) == 0) &&
             statement.size() > 10 &&
             std::isspace(static_cast<unsigned char>(statement[10]));
    }

    /**
     * Walk the statements of @p file and of the files it includes (depth
     * first, as deal.II reads them), recording where each entry is set.
     * Include cycles, included directories and missing included files are
     * errors naming the `include` line.
     */
    void
    scan_file(const std::string        &file,
              std::vector<std::string> &sections,
              std::vector<std::string> &include_stack,
              std::vector<std::string> &open_files,
              Locations                &l)
    {
      namespace fs = std::filesystem;
      const std::string where =
        include_stack.empty() ? "" : include_stack.back() + ": ";
      std::error_code   ec;
      const std::string canonical = fs::weakly_canonical(file, ec).string();
      for (std::size_t i = 0; i < open_files.size(); ++i)
        AssertThrow(open_files[i] != canonical,
                    dealii::ExcMessage(where + "'include " + file +
                                       "' includes " +
                                       (i + 1 == open_files.size() ?
                                          std::string("the file itself") :
                                          "a file that includes this one") +
                                       ": an include cycle"));
      AssertThrow(include_stack.size() < 64,
                  dealii::ExcMessage(where + "includes nested more than 64 "
                                             "deep"));
      const std::vector<std::string> lines =
        read_lines(file, include_stack.empty() ? "" : include_stack.back());
      open_files.push_back(canonical);
      for (unsigned int i = 0; i < lines.size(); ++i)
        {
          const unsigned int number    = i + 1;
          const std::string  statement = trim(strip_comment(lines[i]));
          if (is_subsection(statement))
            sections.push_back(collapse_spaces(statement.substr(11)));
          else if ((statement == "end" || statement == "END") &&
                   !sections.empty())
            sections.pop_back();
          else if (is_set(statement))
            {
              const auto  eq   = statement.find('=');
              std::string name = collapse_spaces(statement.substr(
                4, eq == std::string::npos ? std::string::npos : eq - 4));
              std::string path;
              for (const auto &s : sections)
                path += s + "/";
              l.entries[path + name] = Location{file, number};
            }
          else if (is_include(statement))
            {
              const std::string included = trim(statement.substr(7));
              include_stack.push_back(file + ":" + std::to_string(number));
              AssertThrow(!included.empty(),
                          dealii::ExcMessage(include_stack.back() +
                                             ": 'include' names no file"));
              scan_file(included, sections, include_stack, open_files, l);
              include_stack.pop_back();
            }
        }
      open_files.pop_back();
    }

    /** @p text, shortened in the middle if it is very long. */
    std::string
    shorten(const std::string &text, const std::size_t length = 200)
    {
      if (text.size() <= length)
        return text;
      return text.substr(0, length / 2) + " [... " +
             std::to_string(text.size() - length) + " more characters ...] " +
             text.substr(text.size() - length / 2);
    }
  } // namespace

  namespace
  {
    /**
     * The lines of @p file into @p text, with the files it includes inlined
     * in their place (deal.II would read those itself, byte-order mark and
     * all) and each line's origin into @p origin.
     */
    void
    append_text(const std::string     &file,
                const std::string     &include_line,
                std::string           &text,
                std::vector<Location> &origin)
    {
      const std::vector<std::string> lines = read_lines(file, include_line);
      for (unsigned int i = 0; i < lines.size(); ++i)
        {
          const std::string &line    = lines[i];
          const std::string  code    = strip_comment(line);
          const std::string  trimmed = trim(code);
          const std::string  here    = file + ":" + std::to_string(i + 1);
          origin.push_back(Location{file, i + 1});
          if (is_include(trimmed))
            {
              text += '\n';
              append_text(trim(trimmed.substr(7)), here, text, origin);
              continue;
            }
          // white space inside a value is not significant (two spaces in
          // `springing  right`), except on continued lines
          if (is_set(trimmed) && code.find('=') != std::string::npos &&
              (trimmed.empty() || trimmed.back() != '\\'))
            {
              const auto eq = trimmed.find('=');
              text += trimmed.substr(0, eq + 1) + " " +
                      collapse_spaces(trimmed.substr(eq + 1));
              if (code.size() < line.size())
                text += " " + line.substr(code.size());
            }
          else
            text += line;
          text += '\n';
        }
    }
  } // namespace

  std::string
  read_parameter_text(const std::string &filename)
  {
    // the includes are checked first (cycles, directories, missing files)
    record_parameter_locations(filename);
    std::string text;
    append_text(filename, "", text, locations().text_lines);
    return text;
  }

  bool
  parameter_is_set(const std::string &full_path)
  {
    return locations().entries.count(full_path) > 0;
  }

  void
  record_parameter_locations(const std::string &filename)
  {
    Locations &l = locations();
    l.filename   = filename;
    l.entries.clear();
    std::vector<std::string> sections;
    std::vector<std::string> include_stack;
    std::vector<std::string> open_files;
    Locations                found;
    found.filename = filename;
    scan_file(filename, sections, include_stack, open_files, found);
    l = found;
  }

  std::string
  parameter_location(const std::string &full_path)
  {
    const Locations &l = locations();
    if (l.filename.empty())
      return "";
    const auto it = l.entries.find(collapse_spaces(full_path));
    if (it == l.entries.end())
      return l.filename + " (default value)";
    return it->second.file + ":" + std::to_string(it->second.line);
  }

  std::string
  parameter_at_line(const unsigned int line)
  {
    return parameter_at_line(locations().filename, line);
  }

  std::string
  parameter_at_line(const std::string &file, const unsigned int line)
  {
    for (const auto &entry : locations().entries)
      if (entry.second.line == line && entry.second.file == file)
        return entry.first;
    return "";
  }

  std::string
  explain_parse_error(const std::string &raw)
  {
    std::string message = raw;
    // "file:line: text", where file is the parameter file or one it
    // includes; no std::regex: values may be megabytes long
    const Locations &l = locations();
    std::string      file;
    // a line of the text with the includes inlined: name its own file
    if (!l.filename.empty() && message.rfind(l.filename + ":", 0) == 0)
      {
        const std::size_t end = message.find(':', l.filename.size() + 1);
        try
          {
            const unsigned int n = dealii::Utilities::string_to_int(
              message.substr(l.filename.size() + 1,
                             end - l.filename.size() - 1));
            if (end != std::string::npos && n >= 1 &&
                n <= l.text_lines.size() &&
                (l.text_lines[n - 1].file != l.filename ||
                 l.text_lines[n - 1].line != n))
              message = l.text_lines[n - 1].file + ":" +
                        std::to_string(l.text_lines[n - 1].line) +
                        raw.substr(end);
          }
        catch (...)
          {}
      }
    if (!l.filename.empty() && message.rfind(l.filename + ":", 0) == 0)
      file = l.filename;
    else
      for (const auto &entry : l.entries)
        if (message.rfind(entry.second.file + ":", 0) == 0)
          file = entry.second.file;
    if (file.empty())
      return shorten(message, 1000);
    const std::size_t colon = message.find(':', file.size() + 1);
    if (colon == std::string::npos)
      return shorten(message, 1000);
    unsigned int line = 0;
    try
      {
        line = dealii::Utilities::string_to_int(
          message.substr(file.size() + 1, colon - file.size() - 1));
      }
    catch (...)
      {
        return shorten(message, 1000);
      }
    const std::string path          = parameter_at_line(file, line);
    std::string       text          = trim(message.substr(colon + 1));
    const std::string no_subsection = "There is no such subsection to be "
                                      "entered:";
    if (path.empty() && text.rfind(no_subsection, 0) == 0)
      return file + ":" + std::to_string(line) + ": subsection '" +
             shorten(trim(text.substr(no_subsection.size()))) +
             "': no such subsection is declared here (misspelt, or in the "
             "wrong place? masonry --print-parameters lists every entry)";
    if (path.empty())
      return shorten(message, 1000);

    const std::string value   = "The entry value ";
    const std::string named   = " for the entry named ";
    const std::string pattern = "does not match the given pattern";
    if (text.rfind("No entry with name", 0) == 0 &&
        text.find("was declared in the current subsection") !=
          std::string::npos)
      text = "no such entry is declared here (misspelt, or in the wrong "
             "subsection? masonry --print-parameters lists every entry)";
    else if (text.rfind(value, 0) == 0 &&
             text.find(pattern) != std::string::npos)
      {
        const std::size_t end   = text.find(named);
        const std::size_t given = text.rfind(pattern);
        std::string       v = end == std::string::npos || end < value.size() ?
                                "" :
                                trim(text.substr(value.size(), end - value.size()));
        std::string       p = trim(text.substr(given + pattern.size()));
        if (!p.empty() && p[0] == ':')
          p = trim(p.substr(1));
        for (std::string *t : {&v, &p})
          if (t->size() > 1 && t->front() == '<' && t->back() == '>')
            *t = t->substr(1, t->size() - 2);
        text = "the value '" + shorten(v) + "' does not match the pattern " +
               shorten(p, 600);
        // a number out of its range: say so in plain words
        const std::string dbl =
          p.rfind("[Integer range ", 0) == 0 ? "[Integer range " : "[Double ";
        const std::string dots = "...";
        if (p.rfind(dbl, 0) == 0 && p.find(dots) != std::string::npos)
          {
            const auto        d   = p.find(dots);
            const std::string low = p.substr(dbl.size(), d - dbl.size());
            const auto        sp  = p.find(' ', d);
            const std::string high =
              p.substr(d + 3, sp == std::string::npos ? sp : sp - d - 3);
            text = "the value '" + shorten(v) +
                   "' is not a number in the range [" + low + ", " + high +
                   "] (the unit is in the entry's documentation)";
          }
      }
    return file + ":" + std::to_string(line) + ": entry '" + shorten(path) +
           "': " + shorten(text, 1000);
  }

  dealii::ExcMessage
  ExcParameter(const std::string &entry, const std::string &message)
  {
    const std::string section = plugins::current_parse_path();
    std::string       path    = section.empty() ? entry : section + "/" + entry;
    // checks made while running have no parse path: an entry of that name
    // set once in the file is the one meant
    if (!parameter_is_set(path))
      {
        std::string match;
        for (const auto &e : locations().entries)
          if (e.first.size() > entry.size() &&
              e.first.compare(e.first.size() - entry.size() - 1,
                              entry.size() + 1,
                              "/" + entry) == 0)
            match = match.empty() ? e.first : std::string("\n");
        if (!match.empty() && match != "\n")
          path = match;
      }
    const std::string where = parameter_location(path);
    return dealii::ExcMessage((where.empty() ? "" : where + ": ") + "entry '" +
                              path + "': " + message);
  }

  std::string
  one_line_message(const std::exception &exc)
  {
    std::string text;
    if (const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        deal->print_info(info);
        text = info.str();
        if (collapse_spaces(text).empty())
          text = deal->get_exc_name();
      }
    else
      text = exc.what();
    text = collapse_spaces(text);
    // deal.II's parameter messages start with "Line <n> of file <f>:";
    // present them as "f:n:" like a compiler does.
    if (text.rfind("Line <", 0) == 0)
      {
        const auto close = text.find('>');
        const auto file0 = text.find("of file <");
        if (close != std::string::npos && file0 != std::string::npos)
          {
            // "of file <f>: text", or "of file <f: text" in some messages
            std::size_t name_end = text.find(">:", file0);
            std::size_t rest     = name_end + 2;
            const auto  colon    = text.find(": ", file0);
            if (colon != std::string::npos &&
                (name_end == std::string::npos || colon < name_end))
              {
                name_end = colon;
                rest     = colon + 1;
              }
            if (name_end != std::string::npos)
              text = text.substr(file0 + 9, name_end - file0 - 9) + ":" +
                     text.substr(6, close - 6) + ":" + text.substr(rest);
          }
      }
    return shorten(text, 2000);
  }

  double
  positive_entry(dealii::ParameterHandler &prm, const std::string &entry)
  {
    const double v = prm.get_double(entry);
    AssertThrow(v > 0,
                ExcParameter(entry, "must be positive, got " + prm.get(entry)));
    return v;
  }

  std::vector<std::pair<std::string, std::string>>
  parameter_values(const dealii::ParameterHandler &prm)
  {
    // the handler's own short form, one `set' line an entry: "subsection
    // NAME", "set NAME = VALUE" (NAME padded with blanks) and "end"
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    std::istringstream                               in(text.str());
    std::vector<std::string>                         path;
    std::vector<std::pair<std::string, std::string>> values;
    std::string                                      line;
    while (std::getline(in, line))
      {
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(trim(line.substr(11)));
        else if (line == "end" && !path.empty())
          path.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const std::size_t equal = line.find('=');
            std::string       name;
            for (const auto &p : path)
              name += p + "/";
            name += trim(line.substr(4, equal - 4));
            values.emplace_back(name,
                                equal == std::string::npos ?
                                  std::string() :
                                  trim(line.substr(equal + 1)));
          }
      }
    return values;
  }

  std::vector<double>
  split_doubles(const std::string &text, const std::string &entry)
  {
    std::vector<double> values;
    for (const auto &item : dealii::Utilities::split_string_list(text, ','))
      {
        try
          {
            values.push_back(dealii::Utilities::string_to_double(item));
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcParameter(entry, "'" + item + "' is not a number"));
          }
      }
    return values;
  }
} // namespace masonry
