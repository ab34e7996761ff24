#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/utilities.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace masonry
{
  namespace
  {
    struct Locations
    {
      std::string                         filename;
      std::map<std::string, unsigned int> line_of_entry;
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
      const auto b = s.find_first_not_of(" \t\r");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t\r");
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
  } // namespace

  void
  record_parameter_locations(const std::string &filename)
  {
    Locations &l = locations();
    l.filename   = filename;
    l.line_of_entry.clear();
    std::ifstream            in(filename);
    std::vector<std::string> sections;
    std::string              line;
    unsigned int             number = 0;
    while (std::getline(in, line))
      {
        ++number;
        line = trim(line.substr(0, line.find('#')));
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(trim(line.substr(11)));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto  eq   = line.find('=');
            std::string name = trim(line.substr(
              4, eq == std::string::npos ? std::string::npos : eq - 4));
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            l.line_of_entry[collapse_spaces(path + name)] = number;
          }
      }
  }

  std::string
  parameter_location(const std::string &full_path)
  {
    const Locations &l = locations();
    if (l.filename.empty())
      return "";
    const auto it = l.line_of_entry.find(full_path);
    if (it == l.line_of_entry.end())
      return l.filename + " (default value)";
    return l.filename + ":" + std::to_string(it->second);
  }

  std::string
  parameter_at_line(const unsigned int line)
  {
    for (const auto &entry : locations().line_of_entry)
      if (entry.second == line)
        return entry.first;
    return "";
  }

  std::string
  explain_parse_error(const std::string &message)
  {
    const std::string &file = locations().filename;
    if (file.empty() || message.rfind(file + ":", 0) != 0)
      return message;
    const std::size_t colon = message.find(':', file.size() + 1);
    if (colon == std::string::npos)
      return message;
    unsigned int line = 0;
    try
      {
        line = dealii::Utilities::string_to_int(
          message.substr(file.size() + 1, colon - file.size() - 1));
      }
    catch (...)
      {
        return message;
      }
    const std::string path = parameter_at_line(line);
    std::string       text = trim(message.substr(colon + 1));
    if (path.empty())
      return message;

    std::smatch match;
    if (std::regex_match(text,
                         match,
                         std::regex("No entry with name <.*> was declared in "
                                    "the current subsection\\.?")))
      text = "no such entry is declared here (misspelt, or in the wrong "
             "subsection? masonry --print-parameters lists every entry)";
    else if (std::regex_match(text,
                              match,
                              std::regex("The entry value (.*) for the entry "
                                         "named .* does not match the given "
                                         "pattern:? ?(.*)")))
      text = "the value '" + match[1].str() + "' does not match the pattern " +
             match[2].str();
    return file + ":" + std::to_string(line) + ": entry '" + path +
           "': " + text;
  }

  dealii::ExcMessage
  ExcParameter(const std::string &entry, const std::string &message)
  {
    const std::string section = plugins::current_parse_path();
    const std::string path    = section.empty() ? entry : section + "/" + entry;
    const std::string where   = parameter_location(path);
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
        const auto file1 =
          file0 == std::string::npos ? file0 : text.find(">:", file0);
        if (close != std::string::npos && file1 != std::string::npos)
          text = text.substr(file0 + 9, file1 - file0 - 9) + ":" +
                 text.substr(6, close - 6) + ":" + text.substr(file1 + 2);
      }
    return text;
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
