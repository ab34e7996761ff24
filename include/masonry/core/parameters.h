/**
 * @file
 * Parameter-file helpers: where an entry stands in the input file, and
 * one-line error messages that name the file, the line and the entry.
 */
#ifndef masonry_core_parameters_h
#define masonry_core_parameters_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace masonry
{
  /**
   * Remember, for every `set` line of @p filename, the full path of the entry
   * ("Geometry model/Barrel vault/Span") and its line number, so that errors
   * found after parsing can point at the input line.
   */
  void
  record_parameter_locations(const std::string &filename);

  /**
   * The text of the parameter file @p filename as given to deal.II: a UTF-8
   * byte-order mark removed, runs of white space inside the values of `set`
   * lines collapsed to one space. Also records the locations of the entries
   * (record_parameter_locations()) and checks the `include` statements of
   * the file and of the files it includes: a missing file, a directory and
   * an include cycle (a file that includes itself) are errors naming the
   * `include` line.
   */
  std::string
  read_parameter_text(const std::string &filename);

  /**
   * Whether the parameter file (or a file it includes) sets the entry
   * @p full_path ("Geometry model/Density").
   */
  bool
  parameter_is_set(const std::string &full_path);

  /**
   * "file.prm:12" for an entry set in the input file, or "file.prm" (with a
   * note that the default is used) when the file does not set it.
   */
  std::string
  parameter_location(const std::string &full_path);

  /**
   * The full path of the entry set on line @p line of the file given to
   * record_parameter_locations(), or "" if no `set` stands on that line.
   */
  std::string
  parameter_at_line(const unsigned int line);

  /** The same for line @p line of @p file (the file or an included one). */
  std::string
  parameter_at_line(const std::string &file, const unsigned int line);

  /**
   * Reword an error of dealii::ParameterHandler::parse_input(), already in
   * one line as "file:line: text" (see one_line_message()), so that it names
   * the full path of the entry set on that line and says what is wrong in
   * plain words: an unknown entry, a value not matching its pattern.
   */
  std::string
  explain_parse_error(const std::string &message);

  /**
   * The exception for a value that passes its pattern but is still wrong
   * (a negative span, a missing CAD file, ...). @p entry is the name of an
   * entry of the subsection being parsed; the message names the file, the
   * line and the full path of the entry.
   */
  dealii::ExcMessage
  ExcParameter(const std::string &entry, const std::string &message);

  /**
   * The text of any exception in one line: deal.II's multi-line messages
   * (without the stack trace) are folded, the noise of its banners removed.
   */
  std::string
  one_line_message(const std::exception &exc);

  /**
   * The physical range of a numeric entry, inclusive, in SI units. A value
   * outside it (1e300, a negative strength, ...) would only show up deep
   * inside a solve as NaN, an endless step redo or a solver abort, so it is
   * rejected when the file is read, with an error naming the entry, its
   * line and the range.
   */
  struct PhysicalRange
  {
    double min = 0;
    double max = 0;
    /** The unit as the documentation prints it: "Pa", "m",
     * "(dimensionless)", ... */
    std::string unit;
  };

  /**
   * Declare the number entry @p name in the present subsection with its
   * physical @p range: the pattern Patterns::Double(min, max), and
   * @p documentation ending with the range ("Physical range, checked when
   * the file is read: 0 to 1e+09 Pa."). What a plugin calls in its
   * declare_parameters() for each entry with a physical meaning, so that
   * the range holds wherever the plugin's entries are declared.
   */
  void
  declare_ranged_entry(dealii::ParameterHandler &prm,
                       const std::string        &name,
                       const std::string        &default_value,
                       const PhysicalRange      &range,
                       const std::string        &documentation);

  /** The same for a whole number of iterations from @p min to @p max
   * (Patterns::Integer; the unit printed is "iterations"). */
  void
  declare_ranged_iterations(dealii::ParameterHandler &prm,
                            const std::string        &name,
                            const std::string        &default_value,
                            const int                 min,
                            const int                 max,
                            const std::string        &documentation);

  /** The same for a list of numbers, each in @p range: exactly @p length
   * of them, or any number of them with @p length = 0, separated by
   * @p separator. */
  void
  declare_ranged_list(dealii::ParameterHandler &prm,
                      const std::string        &name,
                      const std::string        &default_value,
                      const PhysicalRange      &range,
                      const unsigned int        length,
                      const std::string        &separator,
                      const std::string        &documentation);

  /**
   * Give the numeric entries of the core's range table
   * (core/parameter_ranges.cc: the geometry models' entries, whose lengths
   * check_parameter_values() reads; every other plugin declares its ranges
   * with declare_ranged_entry()) that range as their pattern and in their
   * documentation. Called after every plugin has declared its entries.
   */
  void
  declare_parameter_ranges(dealii::ParameterHandler &prm);

  /**
   * Checks of a parsed file that need no model: the function expressions
   * (`Thickness', `Surface load', `Settlement') are parsed and evaluated on
   * sample points of the geometry's box, and must be finite and within
   * their physical range; the numbers of `Point loads' and `Line loads'
   * too. Errors name the entry and its line.
   */
  void
  check_parameter_values(dealii::ParameterHandler &prm);

  /**
   * The value of @p entry of the present subsection of @p prm; throws
   * ExcParameter naming the entry unless it is positive.
   */
  double
  positive_entry(dealii::ParameterHandler &prm, const std::string &entry);

  /**
   * Every entry of @p prm at any depth, whatever its present subsection: the
   * full path ("Wallette/Collar bed gap") and the value, in the order
   * print_parameters() gives them (subsections and entries by name).
   */
  std::vector<std::pair<std::string, std::string>>
  parameter_values(const dealii::ParameterHandler &prm);

  /** Split a comma-separated list of doubles (e.g. a vector entry). */
  std::vector<double>
  split_doubles(const std::string &text, const std::string &entry);
} // namespace masonry

#endif
