/**
 * @file
 * The project's JSON type: nlohmann::json (Debian's nlohmann-json3-dev) with
 * objects in insertion order, as nlohmann::ordered_json, and one rule of
 * its own: a number that is not finite cannot be stored. JSON has no NaN or
 * infinity (nlohmann would write `null`), so a non-finite result is an
 * error where it is put into a document, not a silent `null` in
 * summary.json.
 */
#ifndef masonry_core_json_h
#define masonry_core_json_h

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace masonry
{
  /**
   * Thrown when a number that is not finite is put into a Json value. The
   * driver names the summary member it was meant for and ends the run as
   * `failed'.
   */
  class NonFiniteJsonNumber : public std::domain_error
  {
  public:
    explicit NonFiniteJsonNumber(const double value)
      : std::domain_error("a number that is not finite (" +
                          std::to_string(value) + ") cannot be stored in JSON")
    {}
  };

  namespace internal
  {
    /**
     * nlohmann's serializer, with a check of every floating-point number
     * that goes into a document (also the elements of containers).
     */
    template <typename T, typename = void>
    struct JsonSerializer
    {
      template <typename BasicJson, typename Value>
      static auto
      to_json(BasicJson &j, Value &&value) noexcept(false)
        -> decltype(nlohmann::adl_serializer<T>::to_json(
                      j,
                      std::forward<Value>(value)),
                    void())
      {
        if constexpr (std::is_floating_point_v<std::decay_t<Value>>)
          if (!std::isfinite(value))
            throw NonFiniteJsonNumber(value);
        nlohmann::adl_serializer<T>::to_json(j, std::forward<Value>(value));
      }

      template <typename BasicJson, typename Value>
      static auto
      from_json(BasicJson &&j, Value &value) noexcept(false)
        -> decltype(nlohmann::adl_serializer<T>::from_json(
                      std::forward<BasicJson>(j),
                      value),
                    void())
      {
        nlohmann::adl_serializer<T>::from_json(std::forward<BasicJson>(j),
                                               value);
      }

      template <typename BasicJson>
      static auto
      from_json(BasicJson &&j) noexcept(false)
        -> decltype(nlohmann::adl_serializer<T>::from_json(
          std::forward<BasicJson>(j)))
      {
        return nlohmann::adl_serializer<T>::from_json(
          std::forward<BasicJson>(j));
      }
    };
  } // namespace internal

  /**
   * A JSON value (nlohmann::basic_json): objects keep the order in which
   * their members were added, numbers are written in the shortest form that
   * reads back to the same double, and a non-finite number throws
   * NonFiniteJsonNumber where it is stored.
   */
  using Json = nlohmann::basic_json<nlohmann::ordered_map,
                                    std::vector,
                                    std::string,
                                    bool,
                                    std::int64_t,
                                    std::uint64_t,
                                    double,
                                    std::allocator,
                                    internal::JsonSerializer>;

  /**
   * Parse JSON text (a previous run's summary.json, a test's output).
   * Throws an ExcMessage "malformed JSON: ..." on malformed input.
   */
  Json
  parse_json(const std::string &text);

  /**
   * The path ("a/b[2]") of the first `null' member of @p value, in the order
   * of the document, or "": where a value that could not be stored was
   * meant to go (see NonFiniteJsonNumber).
   */
  std::string
  first_null_member(const Json &value);
} // namespace masonry

#endif
