// The --help text, generated from the settings table: one section per group,
// each option with its value syntax, help, range and unit, default, and the
// commands that take it when not all do.
#include <string>
#include <vector>

#include "options.h"
#include "settings_table.h"

#ifndef DVSGI_VERSION
#define DVSGI_VERSION "unknown"
#endif

namespace dvsgi::app {

namespace {

constexpr size_t kWidth = 100;   // wrap column
constexpr size_t kIndent = 25;   // where the help of every option starts

// Appends `text` word-wrapped at kWidth, continuation lines indented by `indent`;
// `column` is where the current line already is.
void wrap(std::string& out, const std::string& text, size_t indent, size_t column) {
    size_t pos = 0;
    bool first = true;
    while (pos < text.size()) {
        size_t end = text.find(' ', pos);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(pos, end - pos);
        if (!first && column + 1 + word.size() > kWidth) {
            out += "\n" + std::string(indent, ' ');
            column = indent;
        } else if (!first) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        first = false;
        pos = end + 1;
    }
    out += "\n";
}

std::string details(const Setting& s) {
    const RenderOptions defaults;
    std::vector<std::string> parts;
    const std::string range = s.range();
    const bool listed = s.metavar.find('|') != std::string::npos;  // "on|off" says it already
    if (!range.empty() && (s.kind == Kind::Integer || s.kind == Kind::Number))
        parts.push_back(range + (s.unit.empty() || s.unit == "EV" ? "" : " " + s.unit));
    else if (!range.empty() && !listed)
        parts.push_back("one of " + range);
    else if (!s.unit.empty())
        parts.push_back(s.unit);
    if (!s.unset.empty())
        parts.push_back("default: " + s.unset);
    else if (s.kind == Kind::Flag)
        parts.push_back("default off");
    else
        parts.push_back("default " + s.text(defaults));
    if (s.repeatable) parts.push_back("repeatable");
    if (s.commands != kAll) {
        std::string who;
        for (uint32_t c : {kRender, kView, kBench, kSoak})
            if (s.commands & c)
                who += std::string(who.empty() ? "" : ", ") + (c == kRender ? "render" : c == kView ? "view" : c == kBench ? "bench" : "soak");
        parts.push_back(who + " only");
    }
    if (s.apply == Apply::NextFrame) parts.push_back("viewer: next frame");
    std::string d;
    for (const std::string& p : parts) d += (d.empty() ? "" : "; ") + p;
    return d;
}

}  // namespace

std::string usageText() {
    std::string out =
        "dvsgi " DVSGI_VERSION
        " - voxel global illumination renderer (Vulkan)\n"
        "\n"
        "Usage:\n"
        "  dvsgi render [SCENE] [options]   render one frame to an EXR (and a PNG preview)\n"
        "  dvsgi view   [SCENE] [options]   interactive window\n"
        "  dvsgi bench  [SCENE] [options]   time the frame passes\n"
        "  dvsgi soak   [SCENE] [options]   render many frames, changing settings, and check that\n"
        "                                   host and device memory do not grow\n"
        "  dvsgi help | --help | -h         this text\n"
        "  dvsgi --version                  print the version\n"
        "\n"
        "SCENE is a glTF 2.0 (.gltf/.glb), OBJ (+MTL) or PLY file; without one the built-in\n"
        "Cornell box is used. Options take their value as '--opt VALUE' or '--opt=VALUE'; '--'\n"
        "ends the options. Each option says its range, unit and default; options not for all\n"
        "commands name theirs; 'viewer: next frame' marks what the viewer's panel changes\n"
        "without building a new renderer.\n";
    for (const SettingGroup& g : settingGroups()) {
        out += "\n" + g.name + ":\n";
        if (!g.intro.empty()) {
            out += "  ";
            wrap(out, g.intro, 2, 2);
        }
        for (const Setting& s : settingsTable()) {
            if (s.group != g.name) continue;
            std::string head = "  --" + s.name + (s.metavar.empty() ? "" : " " + s.metavar);
            if (head.size() + 1 > kIndent) {
                out += head + "\n" + std::string(kIndent, ' ');
            } else {
                out += head + std::string(kIndent - head.size(), ' ');
            }
            wrap(out, s.help + " (" + details(s) + ")", kIndent, kIndent);
        }
    }
    out +=
        "\n"
        "Exit status: 0 on success, 2 for a bad command line, 3 when --validate saw validation\n"
        "errors, 1 for any other failure.\n";
    return out;
}

}  // namespace dvsgi::app
