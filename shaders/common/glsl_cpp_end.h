// The epilogue of a header that compiles shaders/*.glsl as C++: closes what
// common/glsl_cpp_begin.h opened. No include guard.
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
