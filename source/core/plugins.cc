#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/utilities.h>

#include <map>

namespace masonry
{
  namespace plugins
  {
    namespace
    {
      std::map<std::string, Subsystem> &
      subsystem_map()
      {
        static std::map<std::string, Subsystem> map;
        return map;
      }

      std::vector<std::string> &
      parse_paths()
      {
        static std::vector<std::string> paths;
        return paths;
      }
    } // namespace

    namespace internal
    {
      std::vector<std::string>
      split_list(const std::string &text)
      {
        std::vector<std::string> names;
        for (const auto &name : dealii::Utilities::split_string_list(text, ','))
          if (!name.empty())
            names.push_back(name);
        return names;
      }

      void
      throw_parameter_error(const std::string &section,
                            const std::string &entry,
                            const std::string &message)
      {
        ParsePathScope scope(section);
        AssertThrow(false, ExcParameter(entry, message));
      }
    } // namespace internal

    std::string
    section_name(const std::string &plugin_name)
    {
      std::string s = plugin_name;
      if (!s.empty())
        s[0] =
          static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
      return s;
    }

    unsigned int
    enter_path(dealii::ParameterHandler &prm, const std::string &path)
    {
      unsigned int levels = 0;
      std::size_t  start  = 0;
      while (start < path.size())
        {
          const auto slash = path.find('/', start);
          const auto end   = slash == std::string::npos ? path.size() : slash;
          prm.enter_subsection(path.substr(start, end - start));
          ++levels;
          start = end + 1;
        }
      return levels;
    }

    void
    leave_path(dealii::ParameterHandler &prm, const unsigned int n_levels)
    {
      for (unsigned int i = 0; i < n_levels; ++i)
        prm.leave_subsection();
    }

    ParsePathScope::ParsePathScope(const std::string &path)
    {
      parse_paths().push_back(path);
    }

    ParsePathScope::~ParsePathScope()
    {
      parse_paths().pop_back();
    }

    std::string
    current_parse_path()
    {
      return parse_paths().empty() ? std::string() : parse_paths().back();
    }

    void
    add_subsystem(const Subsystem &subsystem)
    {
      subsystem_map()[subsystem.section + "/" + subsystem.entry] = subsystem;
    }

    std::vector<Subsystem>
    subsystems()
    {
      std::vector<Subsystem> list;
      for (const auto &s : subsystem_map())
        list.push_back(s.second);
      return list;
    }
  } // namespace plugins
} // namespace masonry
