// Builders for the entries of the settings table (app/settings_entries*.cpp):
// each takes the metadata and a binding `ref`, a lambda from RenderOptions& to
// the field it sets, and fills in parse/text/json (and the panel's numeric
// access) for its kind. Internal to the table's source files.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "settings_table.h"

namespace dvsgi::app::table {

// "0.00001", "16384", "-20", "0.5": short, never in exponent form.
std::string formatNumber(double v);

// Digits only: "+5", " 5", "5x", "0x10" and "-1" are all refused.
std::optional<uint64_t> parseUnsigned(std::string_view text);
// A finite number with at least one digit; a leading '+' is allowed ("+1" EV).
std::optional<float> parseFloat(std::string_view text);
// A file name ending in `ext` (any case) with a non-empty stem.
bool hasExtension(std::string_view text, std::string_view ext);

// The metadata every builder takes.
struct Meta {
    std::string name, group, metavar, unit, help;
    uint32_t commands = kAll;
    Apply apply = Apply::Startup;
};

Setting base(const Meta& m, Kind kind);

// Reads through a binding written for mutable options; nothing is written.
template <class F>
decltype(auto) read(const F& ref, const RenderOptions& o) {
    return ref(const_cast<RenderOptions&>(o));
}

template <class F>
using FieldOf = std::remove_reference_t<decltype(std::declval<F>()(std::declval<RenderOptions&>()))>;

template <class F>
Setting flag(const Meta& m, F ref) {
    Setting s = base(m, Kind::Flag);
    s.expected = "no value";
    s.example = "on";
    s.parse = [ref](RenderOptions& o, std::string_view) { return ref(o) = true; };
    s.text = [ref](const RenderOptions& o) { return std::string(read(ref, o) ? "on" : "off"); };
    s.json = [ref](const RenderOptions& o) { return nlohmann::json(bool(read(ref, o))); };
    return s;
}

template <class F>
Setting toggle(const Meta& m, F ref) {
    Setting s = base(m, Kind::Toggle);
    s.choices = {"on", "off"};
    s.expected = "on or off";
    s.parse = [ref](RenderOptions& o, std::string_view v) {
        if (v != "on" && v != "off") return false;
        ref(o) = v == "on";
        return true;
    };
    s.text = [ref](const RenderOptions& o) { return std::string(read(ref, o) ? "on" : "off"); };
    s.json = [ref](const RenderOptions& o) { return nlohmann::json(bool(read(ref, o))); };
    return s;
}

// Unsigned or int fields; values are whole numbers in [lo, hi].
template <class F>
Setting integer(const Meta& m, double lo, double hi, F ref, bool pow2 = false, bool zeroOk = false) {
    using T = FieldOf<F>;
    Setting s = base(m, Kind::Integer);
    s.lo = lo;
    s.hi = hi;
    s.pow2 = pow2;
    s.zeroOk = zeroOk;
    s.expected = pow2 ? s.range() : hi >= 1e6 ? "an integer >= " + formatNumber(lo) : "an integer in " + s.range();
    s.parse = [ref, lo, hi, pow2, zeroOk](RenderOptions& o, std::string_view v) {
        const std::optional<uint64_t> n = parseUnsigned(v);
        if (!n) return false;
        const double d = double(*n);
        const bool zero = zeroOk && *n == 0;
        if (!zero && (d < lo || d > hi || (pow2 && (*n & (*n - 1)) != 0))) return false;
        ref(o) = T(*n);
        return true;
    };
    s.text = [ref](const RenderOptions& o) { return std::to_string(read(ref, o)); };
    s.json = [ref](const RenderOptions& o) { return nlohmann::json(read(ref, o)); };
    s.number = [ref](const RenderOptions& o) { return double(read(ref, o)); };
    s.setNumber = [ref](RenderOptions& o, double v) { ref(o) = T(std::llround(v)); };
    return s;
}

template <class F>
Setting number(const Meta& m, double lo, double hi, F ref) {
    Setting s = base(m, Kind::Number);
    s.lo = lo;
    s.hi = hi;
    s.expected = "a number in " + s.range();
    s.parse = [ref, lo, hi](RenderOptions& o, std::string_view v) {
        const std::optional<float> f = parseFloat(v);
        // In float, as stored: the float nearest 0.00001 lies below the double.
        if (!f || *f < float(lo) || *f > float(hi)) return false;
        ref(o) = *f;
        return true;
    };
    s.text = [ref](const RenderOptions& o) { return formatNumber(read(ref, o)); };
    s.json = [ref](const RenderOptions& o) { return nlohmann::json(read(ref, o)); };
    s.number = [ref](const RenderOptions& o) { return double(read(ref, o)); };
    s.setNumber = [ref](RenderOptions& o, double v) { ref(o) = float(v); };
    return s;
}

// A fixed set of spellings, each for one value of the field. Spellings that
// are numbers ("6", "16") are written to JSON as numbers.
template <class F>
Setting choice(const Meta& m, std::vector<std::pair<std::string, FieldOf<F>>> values, F ref) {
    Setting s = base(m, Kind::Choice);
    for (const auto& [spelling, value] : values) s.choices.push_back(spelling);
    for (size_t i = 0; i < s.choices.size(); ++i)
        s.expected += (i == 0 ? "" : i + 1 == s.choices.size() ? " or " : ", ") + s.choices[i];
    s.parse = [ref, values](RenderOptions& o, std::string_view v) {
        for (const auto& [spelling, value] : values)
            if (v == spelling) {
                ref(o) = value;
                return true;
            }
        return false;
    };
    s.text = [ref, values](const RenderOptions& o) {
        for (const auto& [spelling, value] : values)
            if (read(ref, o) == value) return spelling;
        return std::string("?");
    };
    s.json = [text = s.text](const RenderOptions& o) {
        const std::string t = text(o);
        const std::optional<uint64_t> n = parseUnsigned(t);
        return n ? nlohmann::json(*n) : nlohmann::json(t);
    };
    return s;
}

// A string field; with `ext`, a file name ending in it (or `none` when given).
template <class F>
Setting text(const Meta& m, F ref, std::string ext = "", std::string none = "") {
    Setting s = base(m, Kind::Text);
    if (!ext.empty()) s.expected = "a " + ext + " file name" + (none.empty() ? "" : " or '" + none + "'");
    s.parse = [ref, ext, none](RenderOptions& o, std::string_view v) {
        if (!ext.empty() && !(!none.empty() && v == none) && !hasExtension(v, ext)) return false;
        ref(o) = std::string(v);
        return true;
    };
    s.text = [ref](const RenderOptions& o) { return read(ref, o); };
    s.json = [ref](const RenderOptions& o) { return nlohmann::json(read(ref, o)); };
    return s;
}

}  // namespace dvsgi::app::table
