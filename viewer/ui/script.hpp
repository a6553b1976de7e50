// Scripted viewer runs (`fxview view --script FILE`): one action per line, '#' comments.
//   set NAME VALUE              a parameter, as --set writes it
//   technique NAME              the technique of every object
//   view MODE                   effect | plain | normals | uv | camera | light, for every object
//   mesh NAME                   the selected object's mesh
//   select camera|light|object [N]
//   rotate camera|light|object X Y Z     degrees, intrinsic X then Y then Z, as a mouse drag would
//   pick X Y                    prints the pick of render-view pixel (X, Y) as JSON on stdout
//   screenshot FILE             the whole window, UI included
//   render-screenshot FILE      the render view at its own resolution
//   skybox TEXTURE|off          a cube-map texture of the effect as the background
//   frames N                    lets N frames pass
#pragma once
#include <string>
#include <vector>

namespace fxview::ui {

struct ScriptAction {
    std::string verb;
    std::vector<std::string> arguments;
    int line = 0;
};

// Throws UsageError naming file:line for an unknown action or a wrong number of arguments.
std::vector<ScriptAction> load_script(const std::string& path);

}  // namespace fxview::ui
