// included by glsl_error_in_include.fx
float helper(float x) {
    return x * missing_variable;
}
