// Descriptor binding numbers of every pass (set 0 is pushed per pass; set 1 is
// the scene's texture table). C++ and GLSL both read them from here.
#ifndef DVSGI_SHARED_BINDINGS_H
#define DVSGI_SHARED_BINDINGS_H

#include "common.h"

DVSGI_BEGIN

// Scene geometry passes (G-buffer, shadow maps).
DVSGI_CONST(uint, BIND_GEOM_FRAME, 0);
DVSGI_CONST(uint, BIND_GEOM_DRAWS, 1);
DVSGI_CONST(uint, BIND_GEOM_MATERIALS, 2);
DVSGI_CONST(uint, BIND_GEOM_SHADOW_VIEWS, 3);
DVSGI_CONST(uint, SET_TEXTURES, 1);
DVSGI_CONST(uint, BIND_TEXTURES, 0);
DVSGI_CONST(uint, BIND_TEXTURE_SAMPLER, 1);

// Deferred direct lighting.
DVSGI_CONST(uint, BIND_LIGHT_FRAME, 0);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_BASE, 1);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_NORMAL, 2);
DVSGI_CONST(uint, BIND_LIGHT_GBUF_EMISSION, 3);
DVSGI_CONST(uint, BIND_LIGHT_DEPTH, 4);
DVSGI_CONST(uint, BIND_LIGHT_LIGHTS, 5);
DVSGI_CONST(uint, BIND_LIGHT_SHADOW_VIEWS, 6);
DVSGI_CONST(uint, BIND_LIGHT_SHADOW_MAP, 7);
DVSGI_CONST(uint, BIND_LIGHT_OUT_DIRECT, 8);
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_GRID, 9);         // shadow cones trace the voxel volumes
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_RADIANCE, 10);
DVSGI_CONST(uint, BIND_LIGHT_VOXEL_DIRECTIONAL, 11);  // array of 6
DVSGI_CONST(uint, BIND_LIGHT_OUT_SHADOW, 12);         // mean light visibility

// Composition and resolve to the output size.
DVSGI_CONST(uint, BIND_COMP_DIRECT, 0);
DVSGI_CONST(uint, BIND_COMP_OUT, 1);
DVSGI_CONST(uint, BIND_COMP_DIFFUSE, 2);   // indirect diffuse + AO (internal size)
DVSGI_CONST(uint, BIND_COMP_SPECULAR, 3);
DVSGI_CONST(uint, BIND_COMP_SHADOW, 4);

// Depth-aware upsampling of the traced terms.
DVSGI_CONST(uint, BIND_UP_FRAME, 0);
DVSGI_CONST(uint, BIND_UP_NORMAL, 1);
DVSGI_CONST(uint, BIND_UP_DEPTH, 2);
DVSGI_CONST(uint, BIND_UP_LOW_DIFFUSE, 3);
DVSGI_CONST(uint, BIND_UP_LOW_SPECULAR, 4);
DVSGI_CONST(uint, BIND_UP_OUT_DIFFUSE, 5);
DVSGI_CONST(uint, BIND_UP_OUT_SPECULAR, 6);

// dvsgi view: the renderer's output tone-mapped into the image blitted to the window.
DVSGI_CONST(uint, BIND_PRESENT_RADIANCE, 0);
DVSGI_CONST(uint, BIND_PRESENT_DISPLAY, 1);

DVSGI_END

#endif
