// The epilogue of a header that compiles physics/*/*.glsl as C++: closes what
// physics/common/glsl_cpp_begin.h opened. No include guard.
}  // namespace
}  // namespace skyig::shader
#pragma GCC diagnostic pop
