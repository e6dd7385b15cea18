// The command line, parsed by CLI11 from the settings table: one CLI::App per
// command, one option per table entry that command takes, each handled the
// moment it is parsed (argv order, so the first bad option is the one named
// and a later occurrence of an option wins). CLI11's own messages are never
// shown: every error is one line naming the option, in this program's words.
#include <CLI/CLI.hpp>

#include <algorithm>

#include "options.h"
#include "settings_table.h"

namespace dvsgi::app {

namespace {

// Thrown inside the parser only; parseCommandLine turns it into ParseResult::error.
struct ParseError {
    std::string message;
};

[[noreturn]] void reject(std::string message) { throw ParseError{std::move(message)}; }

bool isHelp(std::string_view a) { return a == "--help" || a == "-h"; }

const char* commandName(uint32_t mask) {
    return mask == kRender ? "render" : mask == kView ? "view" : mask == kBench ? "bench" : "soak";
}

std::string takers(uint32_t commands) {
    std::string t;
    for (uint32_t c : {kRender, kView, kBench, kSoak})
        if (commands & c) t += std::string(t.empty() ? "" : " and ") + "dvsgi " + commandName(c);
    return t;
}

// What CLI11 would not say the way this program does, checked before it
// parses: an empty "--opt=", a value given to a flag, a value missing at the
// end of the line, and an option of another command.
void precheck(const std::vector<std::string>& args, uint32_t command) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--") return;
        if (!a.starts_with("--")) continue;
        const size_t eq = a.find('=');
        const std::string flag = a.substr(0, eq);
        const Setting* s = findSetting(std::string_view(flag).substr(2));
        if (!s) continue;  // CLI11 leaves it over; parseArgs reports it
        if (!(s->commands & command))
            reject(flag + ": an option of " + takers(s->commands) + ", not of dvsgi " + commandName(command) +
                   " (see dvsgi --help)");
        if (!s->takesValue()) {
            if (eq != std::string::npos) reject(flag + ": takes no value, got '" + a.substr(eq + 1) + "'");
        } else if (eq != std::string::npos) {
            if (eq + 1 == a.size()) reject(flag + ": missing value");
        } else if (i + 1 >= args.size()) {
            reject(flag + ": missing value");
        } else {
            ++i;  // its value, whatever it looks like
        }
    }
}

void parseArgs(const std::vector<std::string>& args, uint32_t command, RenderOptions& o) {
    precheck(args, command);
    CLI::App app("dvsgi", std::string("dvsgi ") + commandName(command));
    app.set_help_flag();  // help is answered before parsing (it wins over any error)
    app.allow_extras();   // left-over arguments get this program's messages below

    bool haveScene = false;
    app.add_option("scene", CLI::callback_t([&](const CLI::results_t& r) {
           o.scene = r.empty() ? "" : r.front();
           haveScene = true;
           return true;
       }))->trigger_on_parse();

    for (const Setting& s : settingsTable()) {
        if (!(s.commands & command)) continue;
        const std::string flag = "--" + s.name;
        auto handle = [&o, &s, flag](const CLI::results_t& r) {
            const std::string value = r.empty() ? "" : r.front();
            // A value that is another long option means the value was forgotten
            // (single-dash words pass, so "--exposure -2" works).
            if (s.takesValue() && (value.empty() || value.starts_with("--"))) reject(flag + ": missing value");
            if (!s.parse(o, value))
                reject(flag + ": expected " + s.expected + ", got '" + value + "'");
            if (!o.isGiven(s.name)) o.given.push_back(s.name);
            return true;
        };
        CLI::Option* opt = s.takesValue() ? app.add_option(flag, CLI::callback_t(handle))
                                          : app.add_flag_callback(flag, [handle] { handle({}); });
        opt->trigger_on_parse();
    }

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        reject(std::string(e.what()) + " (see dvsgi --help)");
    }
    // CLI11 leaves over unknown options, a second positional argument, and "--".
    const auto dash = std::find(args.begin(), args.end(), "--");
    for (const std::string& extra : app.remaining()) {
        const bool beforeDash = std::find(args.begin(), dash, extra) != dash;
        if (extra == "--" && !beforeDash) continue;
        if (extra.size() > 1 && extra[0] == '-' && beforeDash)
            reject("unknown option '" + extra.substr(0, extra.find('=')) + "' (see dvsgi --help)");
        if (haveScene) reject("unexpected argument '" + extra + "' (scene already given as '" + o.scene + "')");
        reject("unexpected argument '" + extra + "'");
    }
}

std::string shellQuoted(int argc, const char* const* argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) {
        if (i) s += ' ';
        const std::string a = argv[i] ? argv[i] : "";
        const bool plain = !a.empty() && a.find_first_of(" \t\"'\\$`") == std::string::npos;
        s += plain ? a : "'" + a + "'";
    }
    return s;
}

}  // namespace

ParseResult parseCommandLine(int argc, const char* const* argv) {
    ParseResult result;
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i] ? argv[i] : "");

    if (args.empty()) return result;
    // Asking for help wins over any other problem on the line.
    const auto helpEnd = std::find(args.begin(), args.end(), "--");
    if (std::any_of(args.begin(), helpEnd, isHelp) || args[0] == "help") return result;
    if (args[0] == "--version") {
        result.command = Command::Version;
        return result;
    }

    const std::string& cmd = args[0];
    uint32_t mask = 0;
    if (cmd == "render") result.command = Command::Render, mask = kRender;
    else if (cmd == "view") result.command = Command::View, mask = kView;
    else if (cmd == "bench") result.command = Command::Bench, mask = kBench;
    else if (cmd == "soak") result.command = Command::Soak, mask = kSoak;
    else {
        if (cmd.starts_with("-"))
            result.error = "expected a command before '" + cmd +
                           "': render, view, bench, soak, help or --version (see dvsgi --help)";
        else
            result.error = "unknown command '" + cmd + "' (expected render, view, bench, soak, help or --version)";
        return result;
    }

    try {
        parseArgs({args.begin() + 1, args.end()}, mask, result.render);
        result.render.commandLine = shellQuoted(argc, argv);
    } catch (const ParseError& e) {
        result.error = e.message;
        result.render = RenderOptions{};
    }
    return result;
}

}  // namespace dvsgi::app
