// What the settings table's entries share: value spelling, ranges, the JSON
// record and the mapping of library messages to flags. The entries themselves
// are in settings_entries.cpp and settings_entries_commands.cpp.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>

#include "settings_kinds.h"

namespace dvsgi::app {

namespace table {

std::string formatNumber(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", v);
    std::string s = buf;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

std::optional<uint64_t> parseUnsigned(std::string_view text) {
    // from_chars alone would accept a leading '-' for signed types.
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return c >= '0' && c <= '9';
    });
    uint64_t v = 0;
    if (!digits) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<float> parseFloat(std::string_view text) {
    std::string_view t = text;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    // from_chars would take "inf"/"nan"; demanding a digit makes words like
    // "infinity" fail for the obvious reason.
    const bool hasDigit = std::any_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    float v = 0.0f;
    if (t.empty() || !hasDigit || t.front() == '+') return std::nullopt;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

bool hasExtension(std::string_view text, std::string_view ext) {
    const size_t slash = text.find_last_of('/');
    const std::string_view b = slash == std::string_view::npos ? text : text.substr(slash + 1);
    if (b.size() <= ext.size()) return false;
    return std::equal(ext.begin(), ext.end(), b.end() - ext.size(), [](char a, char c) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(c));
    });
}

Setting base(const Meta& m, Kind kind) {
    Setting s;
    s.name = m.name;
    s.group = m.group;
    s.kind = kind;
    s.metavar = m.metavar;
    s.unit = m.unit;
    s.help = m.help;
    s.commands = m.commands;
    s.apply = m.apply;
    return s;
}

}  // namespace table

std::string Setting::range() const {
    using table::formatNumber;
    switch (kind) {
        case Kind::Integer:
            if (pow2)
                return std::string(zeroOk ? "0 or " : "") + "a power of two in " + formatNumber(lo) + ".." +
                       formatNumber(hi);
            [[fallthrough]];
        case Kind::Number:
            if (hi >= 1e6) return ">= " + formatNumber(lo);
            return formatNumber(lo) + ".." + formatNumber(hi);
        case Kind::Toggle:
        case Kind::Choice: {
            std::string r;
            for (const std::string& c : choices) r += (r.empty() ? "" : "|") + c;
            return r;
        }
        default: return "";
    }
}

const Setting* findSetting(std::string_view name) {
    const std::vector<Setting>& all = settingsTable();
    const auto it = std::find_if(all.begin(), all.end(), [&](const Setting& s) { return s.name == name; });
    return it == all.end() ? nullptr : &*it;
}

nlohmann::json settingsJson(const RenderOptions& o, uint32_t command) {
    nlohmann::json j = nlohmann::json::object();
    for (const Setting& s : settingsTable())
        if (s.commands & command) j[s.name] = s.json(o);
    return j;
}

std::string withFlagNames(const std::string& message) {
    const size_t colon = message.find(':');
    if (colon == std::string::npos || !findSetting(std::string_view(message).substr(0, colon))) return message;
    return "--" + message;
}

}  // namespace dvsgi::app
