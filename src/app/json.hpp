#pragma once
// A minimal JSON writer for the program's --json output: objects, arrays, numbers, strings.
// Numbers are written with 17 significant digits so that they read back bit for bit.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace sweetspot::app {

class Json {
 public:
  static Json number(double v) {
    if (!std::isfinite(v)) return Json("null");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return Json(buf);
  }
  static Json integer(long long v) { return Json(std::to_string(v)); }
  static Json boolean(bool v) { return Json(v ? "true" : "false"); }
  static Json string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      if (c == '\n') { out += "\\n"; continue; }
      out += c;
    }
    return Json(out + "\"");
  }
  static Json array(const std::vector<Json>& items) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i].text_;
    return Json(out + "]");
  }
  static Json numbers(const std::vector<double>& values) {
    std::vector<Json> items;
    for (double v : values) items.push_back(number(v));
    return array(items);
  }

  // An object built key by key, in the order written.
  class Object {
   public:
    Object& add(const std::string& key, const Json& value) {
      text_ += (text_.empty() ? "" : ", ") + string(key).text_ + ": " + value.text_;
      return *this;
    }
    Object& add(const std::string& key, double value) { return add(key, number(value)); }
    Object& add(const std::string& key, const std::string& value) { return add(key, string(value)); }
    operator Json() const { return Json("{" + text_ + "}"); }

   private:
    std::string text_;
  };

  const std::string& text() const { return text_; }

 private:
  explicit Json(std::string text) : text_(std::move(text)) {}
  std::string text_;
};

}  // namespace sweetspot::app
