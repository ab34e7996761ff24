#include <masonry/core/json.h>

#include <deal.II/base/exceptions.h>

namespace masonry
{
  Json
  parse_json(const std::string &text)
  {
    try
      {
        return Json::parse(text);
      }
    catch (const nlohmann::json::exception &exc)
      {
        throw dealii::ExcMessage(std::string("malformed JSON: ") + exc.what());
      }
  }

  std::string
  first_null_member(const Json &value)
  {
    if (value.is_null())
      return "-";
    if (value.is_array())
      for (std::size_t i = 0; i < value.size(); ++i)
        {
          const std::string inner = first_null_member(value[i]);
          if (!inner.empty())
            return "[" + std::to_string(i) + "]" +
                   (inner == "-" ? "" : (inner[0] == '[' ? "" : "/") + inner);
        }
    if (value.is_object())
      for (const auto &member : value.items())
        {
          const std::string inner = first_null_member(member.value());
          if (!inner.empty())
            return member.key() +
                   (inner == "-" ? "" : (inner[0] == '[' ? "" : "/") + inner);
        }
    return "";
  }
} // namespace masonry
