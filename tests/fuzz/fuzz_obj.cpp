// Wavefront OBJ meshes (tinyobjloader behind fxview's own index and number checks).
#include "fuzz_input.hpp"
#include "scene/obj_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    const std::string path = fxview::fuzz::write_input(data, size, "mesh.obj");
    fxview::fuzz::expect_only_fxview_errors([&] { fxview::scene::load_obj(path); });
    return 0;
}
