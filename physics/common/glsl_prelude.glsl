// Prepended by the shader loader to every GLSL program (never included by C++): the GLSL
// side of the definitions physics/common/glsl_cpp.h makes for C++.
#define Float float
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
