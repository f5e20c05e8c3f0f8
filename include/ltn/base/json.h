#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  /**
   * A JSON value for the run summary (`summary.json`, a public interface read
   * by scripts, plots and tests). Objects keep their keys in insertion order
   * so the file reads in the order the run happened. Numbers are written with
   * 17 significant digits, so a reader gets back exactly the double we had;
   * non-finite numbers become `null`.
   *
   * Boost 1.74 (Debian 12) has no Boost.JSON, and property_tree writes every
   * number as a string, hence this small writer.
   */
  class JsonValue
  {
  public:
    /** null */
    JsonValue();
    JsonValue(const double value);
    JsonValue(const int value);
    JsonValue(const unsigned int value);
    JsonValue(const unsigned long value);
    JsonValue(const unsigned long long value);
    JsonValue(const bool value);
    JsonValue(const std::string &value);
    JsonValue(const char *value);

    static JsonValue
    object();
    static JsonValue
    array();

    /** Object member, created (as null) if absent. */
    JsonValue &
    operator[](const std::string &key);

    /** Append to an array. */
    void
    push_back(const JsonValue &value);

    void
    write(std::ostream &out, const unsigned int indent = 0) const;

    bool
    is_null() const
    {
      return kind == Kind::null;
    }

  private:
    enum class Kind
    {
      null,
      number,
      integer,
      boolean,
      string,
      object,
      array
    };

    Kind                                           kind;
    double                                         number  = 0;
    std::int64_t                                   integer = 0;
    bool                                           boolean = false;
    std::string                                    text;
    std::vector<std::pair<std::string, JsonValue>> members;
    std::vector<JsonValue>                         elements;
  };
} // namespace ltn
