/**
 * @file
 * A small JSON value for summary.json: objects keep insertion order, numbers
 * are written in the shortest form that reads back to the same double.
 * Writing and reading go through nlohmann::json (Debian's
 * nlohmann-json3-dev), kept out of this header.
 */
#ifndef masonry_core_json_h
#define masonry_core_json_h

#include <string>
#include <utility>
#include <vector>

namespace masonry
{
  /**
   * A JSON value: null, boolean, number, string, array or object.
   */
  class Json
  {
  public:
    /** The kind of value held. */
    enum class Type
    {
      null,
      boolean,
      number,
      string,
      array,
      object
    };

    Json() = default;
    Json(bool value);
    Json(double value);
    Json(int value);
    Json(unsigned int value);
    Json(long value);
    Json(unsigned long value);
    Json(const char *value);
    Json(const std::string &value);

    /** An empty array. */
    static Json
    array();

    /** An empty object. */
    static Json
    object();

    /** The kind of value held. */
    Type
    type() const;

    /**
     * The member @p key of an object, created (as null) if missing; a null
     * value becomes an object. Existing keys keep their position.
     */
    Json &
    operator[](const std::string &key);

    /** Whether an object has the member @p key. */
    bool
    contains(const std::string &key) const;

    /** Append to an array (a null value becomes an array). */
    void
    push_back(const Json &value);

    /** Number of elements of an array or members of an object. */
    std::size_t
    size() const;

    /** The number held (a number value only). */
    double
    as_number() const;

    /** The boolean held (a boolean value only). */
    bool
    as_bool() const;

    /** The keys of an object, in insertion order. */
    std::vector<std::string>
    keys() const;

    /** Remove the member @p key of an object, if present. */
    void
    erase(const std::string &key);

    /**
     * The paths ("a/b[2]") of every number in this value that is NaN or
     * infinite: such a value cannot be written.
     */
    std::vector<std::string>
    non_finite_members() const;

    /** The string held (a string value only). */
    const std::string &
    as_string() const;

    /** Element @p i of an array. */
    const Json &
    at(const std::size_t i) const;

    /** Member @p key of an object (must exist). */
    const Json &
    at(const std::string &key) const;

    /**
     * The text of this value, indented by @p indent spaces per level.
     * JSON has no NaN or infinity: a non-finite number throws an ExcMessage
     * naming its path instead of being written as null.
     */
    std::string
    dump(const unsigned int indent = 2) const;

    /**
     * Parse JSON text (used to read a previous run's summary.json). Throws
     * an ExcMessage on malformed input.
     */
    static Json
    parse(const std::string &text);

  private:
    Type                                      kind          = Type::null;
    bool                                      boolean_value = false;
    double                                    number_value  = 0;
    std::string                               string_value;
    std::vector<Json>                         array_values;
    std::vector<std::pair<std::string, Json>> object_values;
  };
} // namespace masonry

#endif
