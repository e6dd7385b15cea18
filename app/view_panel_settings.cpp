// The viewer panel's settings, generated from the settings table: one header
// per group, one widget per setting the viewer takes (slider ranges = the
// table's ranges), the table's help as the tooltip. A change to a 'next frame'
// setting is reported while it is being made; a change that needs a new
// renderer only when the widget is released, so dragging never rebuilds.
#include "view_panel_settings.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "render/renderer.h"
#include "settings_table.h"
#include "vxgi/volumes.h"

namespace dvsgi::app {

namespace {

// Drawn elsewhere: the window decides the size, the View header the camera,
// the Lights header each light's occlusion mode.
bool drawnElsewhere(const Setting& s) {
    return s.name == "width" || s.name == "height" || s.name == "camera" || s.name == "light-occlusion";
}

bool onPanel(const Setting& s) {
    return (s.commands & kView) && s.apply != Apply::Startup && !drawnElsewhere(s);
}

void tooltip(const Setting& s) {
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("--%s %s\n%s%s", s.name.c_str(), s.metavar.c_str(), s.help.c_str(),
                          s.apply == Apply::NewRenderer ? "\n(builds a new renderer)" : "");
}

// A combo over spellings; true when another one was picked.
bool combo(const Setting& s, RenderOptions& o, const std::vector<std::string>& choices) {
    const std::string current = s.text(o);
    bool changed = false;
    if (ImGui::BeginCombo(s.name.c_str(), current.c_str())) {
        for (const std::string& c : choices)
            if (ImGui::Selectable(c.c_str(), c == current) && c != current) changed = s.parse(o, c);
        ImGui::EndCombo();
    }
    tooltip(s);
    return changed;
}

std::vector<std::string> powersOfTwo(const Setting& s) {
    std::vector<std::string> out;
    if (s.zeroOk) out.push_back("0");
    for (double n = s.lo; n <= s.hi; n *= 2) out.push_back(std::to_string(uint64_t(n)));
    return out;
}

struct Edit {
    bool changed = false;   // the value differs from last frame
    bool released = false;  // a slider or drag was let go after changing it
};

Edit numberWidget(const Setting& s, RenderOptions& o) {
    Edit e;
    // Wide ranges (0..1000 and more) are unusable on a linear slider.
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp | (s.hi - s.lo > 100.0 ? ImGuiSliderFlags_Logarithmic : 0);
    const std::string label = s.name + (s.unit.empty() ? "" : " (" + s.unit + ")");
    if (s.kind == Kind::Integer) {
        int v = int(s.number(o));
        const int hi = int(std::min(s.hi, 1e9));
        e.changed = ImGui::SliderInt(label.c_str(), &v, int(s.lo), hi, "%d", flags);
        if (e.changed) s.setNumber(o, v);
    } else {
        float v = float(s.number(o));
        e.changed = ImGui::SliderFloat(label.c_str(), &v, float(s.lo), float(s.hi), "%.3f", flags);
        if (e.changed) s.setNumber(o, v);
    }
    e.released = ImGui::IsItemDeactivatedAfterEdit();
    tooltip(s);
    return e;
}

// --voxel-box: off = the scene's bounds; on starts from the current grid.
Edit voxelBox(const Setting& s, RenderOptions& o, const render::Renderer& renderer) {
    Edit e;
    render::RenderSettings& r = o.settings;
    if (ImGui::Checkbox("voxel-box (else scene bounds)", &r.hasVoxelBox)) {
        const vxgi::VoxelVolumes* v = renderer.volumes();
        if (r.hasVoxelBox && v && !(r.voxelBoxMin.x < r.voxelBoxMax.x)) {
            r.voxelBoxMin = v->grid.origin;
            r.voxelBoxMax = v->grid.origin + v->grid.voxelSize * float(v->grid.n);
        }
        e.released = true;
    }
    tooltip(s);
    if (r.hasVoxelBox) {
        ImGui::DragFloat3("box min (m)", &r.voxelBoxMin.x, 0.01f);
        e.released |= ImGui::IsItemDeactivatedAfterEdit();
        ImGui::DragFloat3("box max (m)", &r.voxelBoxMax.x, 0.01f);
        e.released |= ImGui::IsItemDeactivatedAfterEdit();
    }
    // An empty box cannot hold a grid: wait until min < max on every axis.
    if (r.hasVoxelBox && !glm::all(glm::lessThan(r.voxelBoxMin, r.voxelBoxMax))) e.released = false;
    return e;
}

// --bounces auto|K.
Edit bounces(const Setting& s, RenderOptions& o) {
    Edit e;
    bool automatic = s.text(o) == "auto";
    if (ImGui::Checkbox("bounces: auto (feedback, one per frame)", &automatic)) {
        e.changed = s.parse(o, automatic ? "auto" : std::to_string(o.settings.voxelLight.bounces));
    }
    tooltip(s);
    if (!automatic) {
        int k = int(o.settings.voxelLight.bounces);
        if (ImGui::SliderInt("bounces per frame", &k, int(s.lo), int(s.hi), "%d", ImGuiSliderFlags_AlwaysClamp))
            e.changed |= s.parse(o, std::to_string(k));
        tooltip(s);
    }
    return e;
}

Edit widget(const Setting& s, RenderOptions& o, const render::Renderer& renderer) {
    Edit e;
    switch (s.kind) {
        case Kind::Flag:
        case Kind::Toggle: {
            bool on = s.text(o) == "on";
            if (ImGui::Checkbox(s.name.c_str(), &on)) e.changed = s.parse(o, on ? "on" : "off");
            tooltip(s);
            return e;
        }
        case Kind::Choice: e.changed = combo(s, o, s.choices); return e;
        case Kind::Integer:
            if (s.pow2) {
                e.changed = combo(s, o, powersOfTwo(s));
                return e;
            }
            return numberWidget(s, o);
        case Kind::Number: return numberWidget(s, o);
        case Kind::Special:
            if (s.name == "voxel-box") return voxelBox(s, o, renderer);
            if (s.name == "bounces") return bounces(s, o);
            return e;
        case Kind::Text: return e;
    }
    return e;
}

}  // namespace

bool settingsWidgets(RenderOptions& o, const render::Renderer& renderer) {
    bool apply = false;
    for (const SettingGroup& g : settingGroups()) {
        const std::vector<Setting>& table = settingsTable();
        const bool any = std::any_of(table.begin(), table.end(),
                                     [&](const Setting& s) { return s.group == g.name && onPanel(s); });
        if (!any || !ImGui::CollapsingHeader(g.name.c_str())) continue;
        ImGui::PushID(g.name.c_str());
        for (const Setting& s : table) {
            if (s.group != g.name || !onPanel(s)) continue;
            const Edit e = widget(s, o, renderer);
            // Sliders of settings that need new resources commit when let go;
            // one-click widgets (combos, checkboxes) at once.
            const bool oneClick = s.kind != Kind::Integer && s.kind != Kind::Number && s.name != "voxel-box";
            if (s.apply == Apply::NextFrame) apply |= e.changed || e.released;
            if (s.apply == Apply::NewRenderer) apply |= e.released || (oneClick && e.changed);
        }
        ImGui::PopID();
    }
    return apply;
}

}  // namespace dvsgi::app
