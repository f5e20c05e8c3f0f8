#include <ltn/base/json.h>

#include <cmath>
#include <cstdio>

namespace ltn
{
  JsonValue::JsonValue()
    : kind(Kind::null)
  {}

  JsonValue::JsonValue(const double value)
    : kind(Kind::number)
    , number(value)
  {}

  JsonValue::JsonValue(const int value)
    : kind(Kind::integer)
    , integer(value)
  {}

  JsonValue::JsonValue(const unsigned int value)
    : kind(Kind::integer)
    , integer(value)
  {}

  JsonValue::JsonValue(const unsigned long value)
    : kind(Kind::integer)
    , integer(static_cast<std::int64_t>(value))
  {}

  JsonValue::JsonValue(const unsigned long long value)
    : kind(Kind::integer)
    , integer(static_cast<std::int64_t>(value))
  {}

  JsonValue::JsonValue(const bool value)
    : kind(Kind::boolean)
    , boolean(value)
  {}

  JsonValue::JsonValue(const std::string &value)
    : kind(Kind::string)
    , text(value)
  {}

  JsonValue::JsonValue(const char *value)
    : kind(Kind::string)
    , text(value)
  {}



  JsonValue
  JsonValue::object()
  {
    JsonValue v;
    v.kind = Kind::object;
    return v;
  }



  JsonValue
  JsonValue::array()
  {
    JsonValue v;
    v.kind = Kind::array;
    return v;
  }



  JsonValue &
  JsonValue::operator[](const std::string &key)
  {
    if (kind == Kind::null)
      kind = Kind::object;
    for (auto &member : members)
      if (member.first == key)
        return member.second;
    members.emplace_back(key, JsonValue());
    return members.back().second;
  }



  void
  JsonValue::push_back(const JsonValue &value)
  {
    if (kind == Kind::null)
      kind = Kind::array;
    elements.push_back(value);
  }



  namespace
  {
    void
    write_string(std::ostream &out, const std::string &s)
    {
      out << '"';
      for (const char c : s)
        switch (c)
          {
            case '"':
              out << "\\\"";
              break;
            case '\\':
              out << "\\\\";
              break;
            case '\n':
              out << "\\n";
              break;
            case '\t':
              out << "\\t";
              break;
            default:
              out << c;
          }
      out << '"';
    }
  } // namespace



  void
  JsonValue::write(std::ostream &out, const unsigned int indent) const
  {
    const std::string pad(indent + 2, ' ');
    switch (kind)
      {
        case Kind::null:
          out << "null";
          break;
        case Kind::number:
          if (std::isfinite(number))
            {
              char buffer[32];
              std::snprintf(buffer, sizeof(buffer), "%.17g", number);
              out << buffer;
            }
          else
            out << "null";
          break;
        case Kind::integer:
          out << integer;
          break;
        case Kind::boolean:
          out << (boolean ? "true" : "false");
          break;
        case Kind::string:
          write_string(out, text);
          break;
        case Kind::object:
          out << "{";
          for (std::size_t i = 0; i < members.size(); ++i)
            {
              out << (i == 0 ? "\n" : ",\n") << pad;
              write_string(out, members[i].first);
              out << ": ";
              members[i].second.write(out, indent + 2);
            }
          out << (members.empty() ? "" : "\n" + std::string(indent, ' '))
              << "}";
          break;
        case Kind::array:
          out << "[";
          for (std::size_t i = 0; i < elements.size(); ++i)
            {
              out << (i == 0 ? "\n" : ",\n") << pad;
              elements[i].write(out, indent + 2);
            }
          out << (elements.empty() ? "" : "\n" + std::string(indent, ' '))
              << "]";
          break;
      }
  }
} // namespace ltn
