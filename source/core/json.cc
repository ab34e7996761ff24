#include <masonry/core/json.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace masonry
{
  Json::Json(bool value)
    : kind(Type::boolean)
    , boolean_value(value)
  {}

  Json::Json(double value)
    : kind(Type::number)
    , number_value(value)
  {}

  Json::Json(int value)
    : Json(static_cast<double>(value))
  {}

  Json::Json(unsigned int value)
    : Json(static_cast<double>(value))
  {}

  Json::Json(long value)
    : Json(static_cast<double>(value))
  {}

  Json::Json(unsigned long value)
    : Json(static_cast<double>(value))
  {}

  Json::Json(const char *value)
    : kind(Type::string)
    , string_value(value)
  {}

  Json::Json(const std::string &value)
    : kind(Type::string)
    , string_value(value)
  {}

  Json
  Json::array()
  {
    Json j;
    j.kind = Type::array;
    return j;
  }

  Json
  Json::object()
  {
    Json j;
    j.kind = Type::object;
    return j;
  }

  Json::Type
  Json::type() const
  {
    return kind;
  }

  Json &
  Json::operator[](const std::string &key)
  {
    if (kind == Type::null)
      kind = Type::object;
    Assert(kind == Type::object, dealii::ExcMessage("JSON value is no object"));
    for (auto &member : object_values)
      if (member.first == key)
        return member.second;
    object_values.emplace_back(key, Json());
    return object_values.back().second;
  }

  bool
  Json::contains(const std::string &key) const
  {
    for (const auto &member : object_values)
      if (member.first == key)
        return true;
    return false;
  }

  void
  Json::push_back(const Json &value)
  {
    if (kind == Type::null)
      kind = Type::array;
    Assert(kind == Type::array, dealii::ExcMessage("JSON value is no array"));
    array_values.push_back(value);
  }

  std::size_t
  Json::size() const
  {
    return kind == Type::array ? array_values.size() : object_values.size();
  }

  double
  Json::as_number() const
  {
    AssertThrow(kind == Type::number,
                dealii::ExcMessage("JSON value is not a number"));
    return number_value;
  }

  const std::string &
  Json::as_string() const
  {
    AssertThrow(kind == Type::string,
                dealii::ExcMessage("JSON value is not a string"));
    return string_value;
  }

  const Json &
  Json::at(const std::size_t i) const
  {
    AssertThrow(kind == Type::array && i < array_values.size(),
                dealii::ExcMessage("JSON array index out of range"));
    return array_values[i];
  }

  const Json &
  Json::at(const std::string &key) const
  {
    for (const auto &member : object_values)
      if (member.first == key)
        return member.second;
    AssertThrow(false, dealii::ExcMessage("JSON object has no member " + key));
    return *this;
  }

  namespace
  {
    using ordered_json = nlohmann::ordered_json;

    void
    to_nlohmann(const Json &value, ordered_json &out, const std::string &path)
    {
      switch (value.type())
        {
          case Json::Type::null:
            out = nullptr;
            break;
          case Json::Type::boolean:
            out = value.as_bool();
            break;
            case Json::Type::number: {
              const double x = value.as_number();
              // JSON has no NaN or infinity; a result that is not a number
              // must never be written as null or silently dropped
              AssertThrow(std::isfinite(x),
                          dealii::ExcMessage(
                            "refusing to write the non-finite value " +
                            std::string(std::isnan(x) ? "nan" :
                                        x > 0         ? "inf" :
                                                        "-inf") +
                            " of '" + (path.empty() ? "(value)" : path) +
                            "' into JSON"));
              // integers are written without a fraction, as before
              if (x == std::floor(x) && std::abs(x) < 9.0e15)
                out = static_cast<long long>(x);
              else
                out = x;
              break;
            }
          case Json::Type::string:
            out = value.as_string();
            break;
          case Json::Type::array:
            out = ordered_json::array();
            for (std::size_t i = 0; i < value.size(); ++i)
              {
                ordered_json element;
                to_nlohmann(value.at(i),
                            element,
                            path + "[" + std::to_string(i) + "]");
                out.push_back(std::move(element));
              }
            break;
          case Json::Type::object:
            out = ordered_json::object();
            for (const auto &key : value.keys())
              {
                ordered_json member;
                to_nlohmann(value.at(key),
                            member,
                            path.empty() ? key : path + "/" + key);
                out[key] = std::move(member);
              }
            break;
        }
    }

    Json
    from_nlohmann(const ordered_json &in)
    {
      switch (in.type())
        {
          case ordered_json::value_t::null:
          case ordered_json::value_t::discarded:
            return Json();
          case ordered_json::value_t::boolean:
            return Json(in.get<bool>());
          case ordered_json::value_t::number_integer:
          case ordered_json::value_t::number_unsigned:
          case ordered_json::value_t::number_float:
            return Json(in.get<double>());
          case ordered_json::value_t::string:
            return Json(in.get<std::string>());
            case ordered_json::value_t::array: {
              Json array = Json::array();
              for (const auto &element : in)
                array.push_back(from_nlohmann(element));
              return array;
            }
            case ordered_json::value_t::object: {
              Json object = Json::object();
              for (const auto &member : in.items())
                object[member.key()] = from_nlohmann(member.value());
              return object;
            }
          case ordered_json::value_t::binary:
            break;
        }
      AssertThrow(false, dealii::ExcMessage("unsupported JSON value"));
      return Json();
    }

    void
    collect_non_finite(const Json               &value,
                       const std::string        &path,
                       std::vector<std::string> &paths)
    {
      switch (value.type())
        {
          case Json::Type::number:
            if (!std::isfinite(value.as_number()))
              paths.push_back(path);
            break;
          case Json::Type::array:
            for (std::size_t i = 0; i < value.size(); ++i)
              collect_non_finite(value.at(i),
                                 path + "[" + std::to_string(i) + "]",
                                 paths);
            break;
          case Json::Type::object:
            for (const auto &key : value.keys())
              collect_non_finite(value.at(key),
                                 path.empty() ? key : path + "/" + key,
                                 paths);
            break;
          default:
            break;
        }
    }
  } // namespace

  bool
  Json::as_bool() const
  {
    AssertThrow(kind == Type::boolean,
                dealii::ExcMessage("JSON value is not a boolean"));
    return boolean_value;
  }

  std::vector<std::string>
  Json::keys() const
  {
    std::vector<std::string> list;
    for (const auto &member : object_values)
      list.push_back(member.first);
    return list;
  }

  void
  Json::erase(const std::string &key)
  {
    for (auto it = object_values.begin(); it != object_values.end(); ++it)
      if (it->first == key)
        {
          object_values.erase(it);
          return;
        }
  }

  std::vector<std::string>
  Json::non_finite_members() const
  {
    std::vector<std::string> paths;
    collect_non_finite(*this, "", paths);
    return paths;
  }

  std::string
  Json::dump(const unsigned int indent) const
  {
    ordered_json out;
    to_nlohmann(*this, out, "");
    return out.dump(static_cast<int>(indent));
  }

  Json
  Json::parse(const std::string &text)
  {
    try
      {
        return from_nlohmann(ordered_json::parse(text));
      }
    catch (const nlohmann::json::exception &exc)
      {
        throw dealii::ExcMessage(std::string("malformed JSON: ") + exc.what());
      }
  }
} // namespace masonry
