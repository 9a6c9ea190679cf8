// What the viewer's user does, as actions: from the window's mouse and keys (window.h) or from
// a --script file that replays them at given frames, for tests and demos.
//
// Script format, one action per line, '#' starts a comment:
//   FRAME key K          press key K: P, S (save), C, H, X, [, ], Esc, or a fly key
//                        w a s d q e (one frame's worth of holding it)
//   FRAME orbit DX DY    drag with the left button by DX, DY pixels
//   FRAME pan DX DY      drag with the right button by DX, DY pixels
//   FRAME wheel STEPS    scroll (dolly); `fov STEPS` with the modifier held
//   FRAME click X Y      click pixel X, Y (path logs of both engines and pathdiff)
// Actions happen before frame FRAME (0 = before the first) is rendered.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

struct ViewAction {
    enum Kind { Key, Orbit, Pan, Wheel, Fov, Click } kind = Key;
    // Key: P, S, C, H (commands), w a s d q e (fly, once per frame held), or 27 for Esc.
    char key = 0;
    double x = 0, y = 0;
};

struct ScriptedAction {
    uint32_t frame = 0;
    ViewAction action;
};

// Throws InputError naming the file and line.
std::vector<ScriptedAction> read_view_script(const std::string& path);

} // namespace tp
