// The settings part of the viewer's panel (app/view_panel_settings.cpp),
// generated from the settings table.
#pragma once

#include "options.h"

namespace dvsgi::app {

// Draws a widget for every setting the viewer can change while running and
// edits `options` in place. Returns true when a renderer setting changed in a
// way to pass on now (Renderer::applySettings, or a new renderer when that
// refuses): continuously for 'next frame' settings, when the widget is let go
// for those that need new resources.
bool settingsWidgets(RenderOptions& options, const render::Renderer& renderer);

}  // namespace dvsgi::app
