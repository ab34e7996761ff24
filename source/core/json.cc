#include <masonry/core/json.h>

#include <deal.II/base/exceptions.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

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
    void
    write_string(std::string &out, const std::string &s)
    {
      out += '"';
      for (const char c : s)
        switch (c)
          {
            case '"':
              out += "\\\"";
              break;
            case '\\':
              out += "\\\\";
              break;
            case '\n':
              out += "\\n";
              break;
            case '\t':
              out += "\\t";
              break;
            case '\r':
              out += "\\r";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char buffer[8];
                  std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
                  out += buffer;
                }
              else
                out += c;
          }
      out += '"';
    }

    void
    newline(std::string       &out,
            const unsigned int indent,
            const unsigned int level)
    {
      if (indent == 0)
        return;
      out += '\n';
      out.append(indent * level, ' ');
    }
  } // namespace

  void
  Json::write(std::string       &out,
              const unsigned int indent,
              unsigned int       level) const
  {
    switch (kind)
      {
        case Type::null:
          out += "null";
          break;
        case Type::boolean:
          out += boolean_value ? "true" : "false";
          break;
        case Type::number:
          if (!std::isfinite(number_value))
            out += "null";
          else
            {
              char       buffer[32];
              const auto result =
                std::to_chars(buffer, buffer + sizeof(buffer), number_value);
              out.append(buffer, result.ptr);
            }
          break;
        case Type::string:
          write_string(out, string_value);
          break;
          case Type::array: {
            out += '[';
            // arrays of numbers stay on one line: curves and vectors read
            // better
            bool flat = true;
            for (const auto &v : array_values)
              flat = flat && (v.kind != Type::array && v.kind != Type::object);
            for (std::size_t i = 0; i < array_values.size(); ++i)
              {
                if (i > 0)
                  out += flat ? ", " : ",";
                if (!flat)
                  newline(out, indent, level + 1);
                array_values[i].write(out, indent, level + 1);
              }
            if (!flat && !array_values.empty())
              newline(out, indent, level);
            out += ']';
            break;
          }
          case Type::object: {
            out += '{';
            for (std::size_t i = 0; i < object_values.size(); ++i)
              {
                if (i > 0)
                  out += ',';
                newline(out, indent, level + 1);
                write_string(out, object_values[i].first);
                out += indent > 0 ? ": " : ":";
                object_values[i].second.write(out, indent, level + 1);
              }
            if (!object_values.empty())
              newline(out, indent, level);
            out += '}';
            break;
          }
      }
  }

  std::string
  Json::dump(const unsigned int indent) const
  {
    std::string out;
    write(out, indent, 0);
    return out;
  }

  namespace
  {
    class Parser
    {
    public:
      explicit Parser(const std::string &text)
        : s(text)
      {}

      Json
      parse_document()
      {
        Json v = value();
        skip();
        AssertThrow(pos == s.size(), error("trailing characters"));
        return v;
      }

    private:
      dealii::ExcMessage
      error(const std::string &what) const
      {
        return dealii::ExcMessage("malformed JSON at character " +
                                  std::to_string(pos) + ": " + what);
      }

      void
      skip()
      {
        while (pos < s.size() &&
               std::isspace(static_cast<unsigned char>(s[pos])))
          ++pos;
      }

      bool
      consume(const std::string &word)
      {
        if (s.compare(pos, word.size(), word) == 0)
          {
            pos += word.size();
            return true;
          }
        return false;
      }

      std::string
      string()
      {
        AssertThrow(pos < s.size() && s[pos] == '"',
                    error("expected a string"));
        ++pos;
        std::string out;
        while (pos < s.size() && s[pos] != '"')
          {
            char c = s[pos++];
            if (c == '\\' && pos < s.size())
              {
                const char e = s[pos++];
                switch (e)
                  {
                    case 'n':
                      c = '\n';
                      break;
                    case 't':
                      c = '\t';
                      break;
                    case 'r':
                      c = '\r';
                      break;
                    case 'u':
                      c = static_cast<char>(
                        std::stoi(s.substr(pos, 4), nullptr, 16));
                      pos += 4;
                      break;
                    default:
                      c = e;
                  }
              }
            out += c;
          }
        AssertThrow(pos < s.size(), error("unterminated string"));
        ++pos;
        return out;
      }

      Json
      value()
      {
        skip();
        AssertThrow(pos < s.size(), error("unexpected end"));
        const char c = s[pos];
        if (c == '{')
          {
            ++pos;
            Json obj = Json::object();
            skip();
            if (consume("}"))
              return obj;
            while (true)
              {
                skip();
                const std::string key = string();
                skip();
                AssertThrow(consume(":"), error("expected ':'"));
                obj[key] = value();
                skip();
                if (consume("}"))
                  return obj;
                AssertThrow(consume(","), error("expected ',' or '}'"));
              }
          }
        if (c == '[')
          {
            ++pos;
            Json arr = Json::array();
            skip();
            if (consume("]"))
              return arr;
            while (true)
              {
                arr.push_back(value());
                skip();
                if (consume("]"))
                  return arr;
                AssertThrow(consume(","), error("expected ',' or ']'"));
              }
          }
        if (c == '"')
          return Json(string());
        if (consume("true"))
          return Json(true);
        if (consume("false"))
          return Json(false);
        if (consume("null"))
          return Json();
        double     number = 0;
        const auto result =
          std::from_chars(s.data() + pos, s.data() + s.size(), number);
        AssertThrow(result.ec == std::errc(), error("expected a value"));
        pos = result.ptr - s.data();
        return Json(number);
      }

      const std::string &s;
      std::size_t        pos = 0;
    };
  } // namespace

  Json
  Json::parse(const std::string &text)
  {
    return Parser(text).parse_document();
  }
} // namespace masonry
