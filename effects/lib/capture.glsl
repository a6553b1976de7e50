// G-buffer capture for GPU-vs-CPU comparisons (docs/cpu-reference.md): fragment shaders that have a
// CPU reference call fx_capture() so that the same draw also writes the inputs of the shared
// vertex stage to colour attachments 1-4 (ignored when the target has only one attachment), and
// attachment 5 what a technique's reference needs besides them (zero unless the shader sets it after
// fx_capture(): cd.fx's Grating stores the pixel's extent in its grating coordinates there).
// Include it inside a fragment shader block, after fragment_inputs.glsl.
layout(location = 1) out vec4 fx_capture_position;  // world position, w = 1: coverage
layout(location = 2) out vec4 fx_capture_normal;    // interpolated (unnormalised) world normal
layout(location = 3) out vec4 fx_capture_uv;        // texture coordinate
layout(location = 4) out vec4 fx_capture_tangent;   // interpolated world tangent (anisotropic BRDFs)
layout(location = 5) out vec4 fx_capture_footprint; // technique-defined, see above

void fx_capture() {
    fx_capture_position = vec4(fs_in.world_position, 1.0);
    fx_capture_normal = vec4(fs_in.normal, 0.0);
    fx_capture_uv = vec4(fs_in.uv, 0.0, 0.0);
    fx_capture_tangent = vec4(fs_in.tangent, 0.0);
    fx_capture_footprint = vec4(0.0);
}

// How far a direction turns from this pixel to the next, the larger of x and y: the blur of an image
// seen along it (thinfilm.fx stores its mirror direction's in fx_capture_footprint for the reference).
float fx_pixel_turn(vec3 direction) { return max(length(dFdxFine(direction)), length(dFdyFine(direction))); }
