/**
 * @file
 * Physical ranges of the numeric entries and the checks of the function
 * expressions that can be made before a model exists: a value out of its
 * range (1e300, a negative strength, ...) would only show up deep inside a
 * solve as NaN, an endless step redo or a solver abort, so it is rejected
 * while the file is read, naming the entry, its line and the range.
 */
#include <masonry/core/parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <unistd.h>

namespace masonry
{
  namespace
  {
    /** One numeric entry with its physical range (inclusive, SI units). */
    struct Range
    {
      std::string path;
      double      min;
      double      max;
      std::string unit;
      /** 0: a number; otherwise a list of exactly this many numbers. */
      unsigned int list_length = 0;
      std::string  separator   = ",";
      /** A list of any length (e.g. `Cycle amplitudes'). */
      bool any_length = false;
    };

    /**
     * An "archive" for ParameterHandler::save() that keeps a pointer to the
     * handler's tree of entries (deal.II stores each entry as a subtree with
     * the children `value', `default_value', `documentation', `pattern',
     * ...) instead of serialising it; read-only.
     */
    struct EntryTree
    {
      const boost::property_tree::ptree *entries = nullptr;

      EntryTree &
      operator&(const dealii::Subscriptor &)
      {
        return *this;
      }

      EntryTree &
      operator&(const boost::property_tree::ptree &tree)
      {
        entries = &tree;
        return *this;
      }

      EntryTree &
      operator&(const std::vector<std::string> &)
      {
        return *this;
      }
    };

    /**
     * A section or entry name as a key of that tree: deal.II's mangling
     * (documented with ParameterHandler's XML output: every character but
     * [a-zA-Z0-9] becomes `_' and its two hex digits, and the name "value" as a
     * whole).
     */
    std::string
    mangle(const std::string &name)
    {
      const char *hex   = "0123456789abcdef";
      const bool  whole = name == "value";
      std::string key;
      for (const char c : name)
        if (!whole && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                       (c >= '0' && c <= '9')))
          key.push_back(c);
        else
          {
            key.push_back('_');
            key.push_back(hex[static_cast<unsigned char>(c) / 16]);
            key.push_back(hex[static_cast<unsigned char>(c) % 16]);
          }
      return key;
    }

    std::vector<Range>
    ranges()
    {
      // every other plugin declares its ranges with its entries
      // (declare_ranged_entry()); the geometry models' stay here together
      // because the checks below read their lengths: they size the box in
      // which the function expressions are sampled, and a length below a
      // millimetre is a degenerate model (Density and Scale factor stay
      // with them, not read by a check)
      std::vector<Range> list = {
        // geometry: negative values are let through to the plugins, which
        // explain what is wrong with them
        {"Geometry model/Density", 0, 1e5, "kg/m^3"},
        {"Geometry model/Arch/Span", -1e3, 1e3, "m"},
        {"Geometry model/Arch/Rise", -1e3, 1e3, "m"},
        {"Geometry model/Arch/Depth", -1e3, 1e3, "m"},
        {"Geometry model/Barrel vault/Span", -1e3, 1e3, "m"},
        {"Geometry model/Barrel vault/Rise", -1e3, 1e3, "m"},
        {"Geometry model/Barrel vault/Length", -1e3, 1e3, "m"},
        {"Geometry model/Cross vault/Span x", -1e3, 1e3, "m"},
        {"Geometry model/Cross vault/Span y", -1e3, 1e3, "m"},
        {"Geometry model/Cross vault/Rise", -1e3, 1e3, "m"},
        {"Geometry model/Dome/Span", -1e3, 1e3, "m"},
        {"Geometry model/Dome/Rise", -1e3, 1e3, "m"},
        {"Geometry model/Panel/Length", -1e3, 1e3, "m"},
        {"Geometry model/Panel/Width", -1e3, 1e3, "m"},
        {"Geometry model/Cad file/Scale factor", 0, 1e3, "(dimensionless)"},
      };
      return list;
    }

    std::vector<std::string>
    split_path(const std::string &path)
    {
      std::vector<std::string> parts;
      std::size_t              start = 0;
      while (true)
        {
          const auto slash = path.find('/', start);
          parts.push_back(path.substr(start, slash - start));
          if (slash == std::string::npos)
            return parts;
          start = slash + 1;
        }
    }

    /** The value of the entry @p path ("a/b/c"); throws if undeclared. */
    std::string
    get(dealii::ParameterHandler &prm, const std::string &path)
    {
      auto              parts = split_path(path);
      const std::string name  = parts.back();
      parts.pop_back();
      return prm.get(parts, name);
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /** A short, one-line form of a function parser's message. */
    std::string
    parser_message(const std::exception &exc)
    {
      std::string text = one_line_message(exc);
      // muParser's own words, without deal.II's banner
      for (const char *key : {"Parser error:", "Message:", "message:"})
        {
          const auto at = text.find(key);
          if (at != std::string::npos)
            text = text.substr(at + std::string(key).size());
        }
      while (!text.empty() && (text[0] == ' ' || text[0] == '<'))
        text.erase(0, 1);
      while (!text.empty() &&
             (text.back() == ' ' || text.back() == '>' || text.back() == '.'))
        text.pop_back();
      return text.substr(0, 200);
    }

    /**
     * Evaluate the function expression @p entry (components separated by
     * ';', variables x, y, z in m) at sample points of the box |x|, |y|,
     * |z| <= @p size; every value must be finite and within +-@p bound.
     */
    void
    check_function(dealii::ParameterHandler &prm,
                   const std::string        &section,
                   const std::string        &entry,
                   const unsigned int        n_components,
                   const double              size,
                   const double              bound,
                   const std::string        &unit,
                   const bool                with_pi)
    {
      const std::string path = section + "/" + entry;
      std::string       expression;
      try
        {
          expression = get(prm, path);
        }
      catch (...)
        {
          return; // the plugin is not built in
        }
      auto fail = [&](const std::string &why) {
        throw dealii::ExcMessage(parameter_location(path) + ": entry '" + path +
                                 "': " + why);
      };
      const auto components =
        dealii::Utilities::split_string_list(expression, ';');
      if (components.size() != n_components)
        fail("needs " + std::to_string(n_components) +
             " ';'-separated function" + (n_components > 1 ? "s" : "") +
             " of x, y, z, got " + std::to_string(components.size()));
      // deal.II prints muParser's errors to the standard error before it
      // throws: keep the screen to the one-line error
      struct Silence
      {
        std::ostringstream sink;
        std::streambuf    *saved = std::cerr.rdbuf(sink.rdbuf());
        int                fd    = -1;
        Silence()
        {
          std::fflush(stderr);
          fd             = dup(2);
          const int null = open("/dev/null", O_WRONLY);
          if (null >= 0)
            {
              dup2(null, 2);
              close(null);
            }
        }
        ~Silence()
        {
          std::cerr.rdbuf(saved);
          std::fflush(stderr);
          if (fd >= 0)
            {
              dup2(fd, 2);
              close(fd);
            }
        }
      } silence;
      dealii::FunctionParser<3>     function(n_components);
      std::map<std::string, double> constants;
      if (with_pi)
        constants["pi"] = M_PI;
      try
        {
          function.initialize("x,y,z", expression, constants);
        }
      catch (const std::exception &exc)
        {
          fail("cannot parse the expression '" + expression.substr(0, 200) +
               "' as a function of x, y, z (" + parser_message(exc) + ").");
        }
      const double samples[] = {0, 0.13, -0.29, 0.5, -0.71, 1};
      double       smallest  = std::numeric_limits<double>::max();
      double       largest   = -std::numeric_limits<double>::max();
      for (const double a : samples)
        for (const double b : samples)
          for (const double c : samples)
            {
              const dealii::Point<3> p(a * size, b * size, c * size);
              for (unsigned int d = 0; d < n_components; ++d)
                {
                  double value = 0;
                  try
                    {
                      value = function.value(p, d);
                    }
                  catch (const std::exception &exc)
                    {
                      fail("cannot parse the expression '" +
                           expression.substr(0, 200) +
                           "' as a function of x, y, z (" +
                           parser_message(exc) + ").");
                    }
                  std::ostringstream where;
                  where << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
                  if (!std::isfinite(value))
                    fail("'" + expression.substr(0, 200) + "' is " +
                         number(value) + " at the point " + where.str() +
                         " m: not a finite number");
                  if (std::abs(value) > bound)
                    fail("'" + expression.substr(0, 200) + "' is " +
                         number(value) + " " + unit + " at the point " +
                         where.str() + " m, outside the physical range [-" +
                         number(bound) + ", " + number(bound) + "] " + unit);
                  if (d == 0)
                    {
                      smallest = std::min(smallest, value);
                      largest  = std::max(largest, value);
                    }
                }
            }
      // a constant thickness of less than a millimetre (1e-300) gives blocks
      // without volume; 0 and negative values are explained by the plugin
      AssertThrow(entry != "Thickness" || smallest != largest ||
                    smallest <= 0 || smallest >= 1e-3,
                  dealii::ExcMessage(parameter_location(path) + ": entry '" +
                                     path + "': " + number(smallest) +
                                     " m is below one millimetre: a "
                                     "degenerate model (the physical range "
                                     "is 0.001 to " +
                                     number(bound) + " m)"));
    }

    /**
     * The numbers of a `;'-separated list of `,'-separated records
     * (`Point loads', `Line loads'): finite and within +-@p bound.
     */
    void
    check_records(dealii::ParameterHandler &prm,
                  const std::string        &path,
                  const double              bound,
                  const std::string        &unit)
    {
      std::string text;
      try
        {
          text = get(prm, path);
        }
      catch (...)
        {
          return;
        }
      for (const auto &record : dealii::Utilities::split_string_list(text, ';'))
        for (const auto &item :
             dealii::Utilities::split_string_list(record, ','))
          {
            double x = 0;
            try
              {
                x = dealii::Utilities::string_to_double(item);
              }
            catch (...)
              {
                continue; // the plugin names the bad number
              }
            AssertThrow(std::isfinite(x) && std::abs(x) <= bound,
                        dealii::ExcMessage(
                          parameter_location(path) + ": entry '" + path +
                          "': the number '" + item.substr(0, 100) +
                          "' is outside the physical range [-" + number(bound) +
                          ", " + number(bound) + "] (" + unit + ")"));
          }
    }
  } // namespace

  namespace
  {
    /** @p documentation with the sentence of @p range at its end. */
    std::string
    with_range(const std::string &documentation,
               const double       min,
               const double       max,
               const std::string &unit)
    {
      return documentation +
             " Physical range, checked when the file is read: " + number(min) +
             " to " + number(max) + " " + unit + ".";
    }
  } // namespace

  void
  declare_ranged_entry(dealii::ParameterHandler &prm,
                       const std::string        &name,
                       const std::string        &default_value,
                       const PhysicalRange      &range,
                       const std::string        &documentation)
  {
    prm.declare_entry(
      name,
      default_value,
      dealii::Patterns::Double(range.min, range.max),
      with_range(documentation, range.min, range.max, range.unit));
  }

  void
  declare_ranged_iterations(dealii::ParameterHandler &prm,
                            const std::string        &name,
                            const std::string        &default_value,
                            const int                 min,
                            const int                 max,
                            const std::string        &documentation)
  {
    prm.declare_entry(name,
                      default_value,
                      dealii::Patterns::Integer(min, max),
                      with_range(documentation, min, max, "iterations"));
  }

  void
  declare_ranged_list(dealii::ParameterHandler &prm,
                      const std::string        &name,
                      const std::string        &default_value,
                      const PhysicalRange      &range,
                      const unsigned int        length,
                      const std::string        &separator,
                      const std::string        &documentation)
  {
    prm.declare_entry(
      name,
      default_value,
      dealii::Patterns::List(dealii::Patterns::Double(range.min, range.max),
                             length,
                             length == 0 ?
                               dealii::Patterns::List::max_int_value :
                               length,
                             separator),
      with_range(documentation, range.min, range.max, range.unit));
  }

  void
  declare_parameter_ranges(dealii::ParameterHandler &prm)
  {
    // the documentation and defaults as declared by the plugins, read from
    // the handler's tree of entries (printing all of it as JSON and parsing
    // that back took half of the CPU time of reading and checking a file)
    EntryTree tree;
    prm.save(tree, 0);
    AssertThrow(tree.entries != nullptr,
                dealii::ExcInternalError("no tree of parameter entries"));
    for (const Range &r : ranges())
      {
        const auto  parts = split_path(r.path);
        std::string key;
        for (const auto &part : parts)
          key += (key.empty() ? "" : ".") + mangle(part);
        const auto node = tree.entries->get_child_optional(key);
        if (!node || !node->get_child_optional("documentation"))
          continue; // a plugin that is not built in
        const std::string default_value =
          node->get<std::string>("default_value");
        std::string documentation = node->get<std::string>("documentation");
        documentation +=
          " Physical range, checked when the file is read: " + number(r.min) +
          " to " + number(r.max) + " " + r.unit + ".";
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        const dealii::Patterns::Double value(r.min, r.max);
        if (r.unit == "iterations")
          prm.declare_entry(parts.back(),
                            default_value,
                            dealii::Patterns::Integer(static_cast<int>(r.min),
                                                      static_cast<int>(r.max)),
                            documentation);
        else if (r.list_length == 0)
          prm.declare_entry(parts.back(), default_value, value, documentation);
        else
          prm.declare_entry(
            parts.back(),
            default_value,
            dealii::Patterns::List(value,
                                   r.any_length ? 0 : r.list_length,
                                   r.any_length ?
                                     dealii::Patterns::List::max_int_value :
                                     r.list_length,
                                   r.separator),
            documentation);
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
      }
  }

  void
  check_parameter_values(dealii::ParameterHandler &prm)
  {
    // the size of the box the expressions are evaluated in: the largest
    // dimension of the selected geometry (m)
    double size = 1;
    try
      {
        std::string section = get(prm, "Geometry model/Model name");
        if (!section.empty())
          section[0] = static_cast<char>(
            std::toupper(static_cast<unsigned char>(section[0])));
        for (const char *entry :
             {"Span", "Rise", "Length", "Span x", "Span y", "Width", "Depth"})
          try
            {
              const double x = dealii::Utilities::string_to_double(
                get(prm, "Geometry model/" + section + "/" + entry));
              if (std::isfinite(x))
                size = std::max(size, std::abs(x));
            }
          catch (...)
            {}
      }
    catch (...)
      {}
    size = std::min(size, 1e3);

    // lengths of the geometry: a vault of less than a millimetre is a
    // degenerate model (0 and negative values are explained by the plugins)
    for (const Range &r : ranges())
      if (r.path.rfind("Geometry model/", 0) == 0 && r.unit == "m")
        try
          {
            const double x =
              dealii::Utilities::string_to_double(get(prm, r.path));
            AssertThrow(x == 0 || std::abs(x) >= 1e-3,
                        dealii::ExcMessage(
                          parameter_location(r.path) + ": entry '" + r.path +
                          "': " + number(x) +
                          " m is below one millimetre: a degenerate model "
                          "(the physical range is 0.001 to " +
                          number(r.max) + " m)"));
          }
        catch (const dealii::ExcMessage &)
          {
            throw;
          }
        catch (...)
          {}

    check_function(prm, "Geometry model", "Thickness", 1, size, 100, "m", true);
    for (const std::string analysis :
         {"Settlement", "Limit load", "Minimum thickness"})
      check_function(prm, analysis, "Surface load", 1, size, 1e8, "Pa", false);
    check_function(prm, "Settlement", "Settlement", 3, size, 100, "m", false);
    check_records(prm, "Limit load/Point loads", 1e9, "N, per unit multiplier");
    check_records(prm,
                  "Limit load/Line loads",
                  1e9,
                  "N/m, per unit multiplier");
  }
} // namespace masonry
