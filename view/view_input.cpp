#include "view/view_input.h"

#include "util/error.h"

#include <fstream>
#include <sstream>

namespace tp {

std::vector<ScriptedAction> read_view_script(const std::string& path) {
    std::ifstream in(path);
    if (!in) input_error("--script {}: cannot open it", path);
    std::vector<ScriptedAction> out;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        ScriptedAction s;
        std::string verb;
        if (!(words >> s.frame)) {
            if (words.eof() && line.find_first_not_of(" \t\r") == std::string::npos) continue;
            input_error("{}:{}: expected a frame number first, got '{}'", path, number, line);
        }
        words >> verb;
        ViewAction& a = s.action;
        bool ok = true;
        if (verb == "key") {
            std::string k;
            ok = bool(words >> k) &&
                 (k == "Esc" ||
                  (k.size() == 1 && std::string("PSCHX[]wasdqe").find(k[0]) != std::string::npos));
            a.kind = ViewAction::Key;
            a.key = k == "Esc" ? char(27) : k[0];
        } else if (verb == "orbit" || verb == "pan" || verb == "click") {
            a.kind = verb == "orbit" ? ViewAction::Orbit
                     : verb == "pan" ? ViewAction::Pan
                                     : ViewAction::Click;
            ok = bool(words >> a.x >> a.y);
        } else if (verb == "wheel" || verb == "fov") {
            a.kind = verb == "wheel" ? ViewAction::Wheel : ViewAction::Fov;
            ok = bool(words >> a.y);
        } else {
            input_error("{}:{}: unknown action '{}' (key, orbit, pan, wheel, fov, click)", path,
                        number, verb);
        }
        std::string extra;
        if (!ok || (words >> extra))
            input_error("{}:{}: malformed '{}' action: '{}'", path, number, verb, line);
        out.push_back(s);
    }
    return out;
}

} // namespace tp
