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
   * Give the numeric entries with a physical range (a table in
   * core/parameter_ranges.cc) that range as their pattern and in their
   * documentation, so that 1e300 or a negative strength is rejected when
   * the file is read. Called after every plugin has declared its entries.
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

  /** Split a comma-separated list of doubles (e.g. a vector entry). */
  std::vector<double>
  split_doubles(const std::string &text, const std::string &entry);
} // namespace masonry

#endif
