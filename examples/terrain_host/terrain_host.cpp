#include "examples/terrain_host/terrain_host.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace terrain_host {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

struct Vec {
  double x, y, z;
};
Vec cross(const Vec& a, const Vec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

// Its rows are the camera's right, up and backward axes.
Mat4 viewMatrix(double yawDeg, double pitchDeg) {
  const double y = yawDeg * kDeg, p = pitchDeg * kDeg;
  const Vec forward{std::sin(y) * std::cos(p), std::cos(y) * std::cos(p), std::sin(p)};
  const Vec right{std::cos(y), -std::sin(y), 0.0};
  const Vec up = cross(right, forward);
  Mat4 m{};
  const Vec rows[3] = {right, up, {-forward.x, -forward.y, -forward.z}};
  for (int r = 0; r < 3; ++r) {
    m[0 * 4 + r] = static_cast<float>(rows[r].x);
    m[1 * 4 + r] = static_cast<float>(rows[r].y);
    m[2 * 4 + r] = static_cast<float>(rows[r].z);
  }
  m[15] = 1.0f;
  return m;
}

Mat4 projectionMatrix(double horizontalFovDeg, double aspect, double near, double far, skyig::DepthConvention depth) {
  const double fx = 1.0 / std::tan(0.5 * horizontalFovDeg * kDeg), fy = fx * aspect;
  Mat4 m{};
  m[0] = static_cast<float>(fx);
  m[5] = static_cast<float>(fy);
  m[11] = -1.0f;
  if (depth == skyig::DepthConvention::ReverseZ) {
    m[14] = static_cast<float>(near);
  } else {
    m[10] = static_cast<float>(-(far + near) / (far - near));
    m[14] = static_cast<float>(-2.0 * far * near / (far - near));
  }
  return m;
}

namespace {

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      float s = 0.0f;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
  return r;
}

GLuint compile(GLenum type, const std::string& text) {
  const char* source = text.c_str();
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("terrain shader: ") + log);
  }
  return s;
}

const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 position;   // metres from the eye, east-north-up
layout(location = 1) in vec3 radiance;   // cd/m^2, lit by skyig's lights on the CPU
layout(location = 2) in float distanceM;
uniform mat4 viewProjection;
out vec3 vRadiance;
out vec3 vOffset;
out float vDistance;
void main() {
  vRadiance = radiance;
  vOffset = position;
  vDistance = distanceM;
  gl_Position = viewProjection * vec4(position, 1.0);
}
)";

// Fogged per fragment by skyig's aerial perspective (skyig::SkyDraw::aerialPerspectiveGlsl,
// pasted after the version line).
const char* kFragment = R"(
in vec3 vRadiance;
in vec3 vOffset;
in float vDistance;
layout(location = 0) out vec4 colour;
layout(location = 1) out float distanceOut;
void main() {
  vec3 transmittance;
  vec3 inScattered = skyigAerialPerspective(vOffset, transmittance);
  colour = vec4(vRadiance * transmittance + inScattered, 1.0);
  distanceOut = vDistance;
}
)";

// The terrain: a flat ground eyeHeight below the eye, a polar grid whose rings grow
// geometrically from 30 m to the terrain's radius (fine near, coarse far, as a terrain's
// levels of detail are), each vertex lit by skyig's lights (the fog is the fragment shader's).
struct Mesh {
  std::vector<float> vertices;  // position, radiance, distance: 7 floats
  std::vector<unsigned> indices;
};

Mesh terrain(const skyig::Sky& sky, const Options& o) {
  const skyig::Light light = sky.light();
  // A Lambertian surface of albedo rho under illuminance E has radiance rho E / pi.
  std::array<double, 3> lit{};
  for (int c = 0; c < 3; ++c)
    lit[static_cast<std::size_t>(c)] =
        o.albedo[static_cast<std::size_t>(c)] / kPi *
        (light.sun.horizontalLux * light.sun.colour[static_cast<std::size_t>(c)] +
         light.moon.horizontalLux * light.moon.colour[static_cast<std::size_t>(c)] +
         light.ambientHorizontalRec709[static_cast<std::size_t>(c)]);
  constexpr int kRings = 40, kSectors = 72;
  Mesh m;
  for (int i = 0; i < kRings; ++i) {
    const double r = 30.0 * std::pow(o.terrainRadiusM / 30.0, i / double(kRings - 1));
    for (int j = 0; j < kSectors; ++j) {
      const double a = 2.0 * kPi * j / kSectors;
      const skyig::Vec3 p{r * std::cos(a), r * std::sin(a), -o.eyeHeightM};
      for (double v : p) m.vertices.push_back(static_cast<float>(v));
      for (std::size_t c = 0; c < 3; ++c) m.vertices.push_back(static_cast<float>(lit[c]));
      m.vertices.push_back(static_cast<float>(std::sqrt(r * r + o.eyeHeightM * o.eyeHeightM)));
    }
  }
  for (int i = 0; i + 1 < kRings; ++i)
    for (int j = 0; j < kSectors; ++j) {
      const unsigned a = static_cast<unsigned>(i * kSectors + j), b = static_cast<unsigned>(i * kSectors + (j + 1) % kSectors);
      const unsigned c = a + kSectors, d = b + kSectors;
      m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
    }
  return m;
}

std::vector<float> readRgb(GLenum attachment, int w, int h) {
  std::vector<float> rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, rgb.data());
  return rgb;
}

}  // namespace

Frame drawFrame(const skyig::Sky& sky, const Options& o, skyig::GlProcAddress getProcAddress) {
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress))) throw std::runtime_error("no OpenGL 4.5 core context");
  skyig::SkyDraw skyDraw(getProcAddress);
  const bool reverseZ = o.depth == skyig::DepthConvention::ReverseZ;

  // The host's framebuffer: linear light (float) and depth, and the terrain's distance.
  GLuint colour = 0, distance = 0, depth = 0, fbo = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &colour);
  glTextureStorage2D(colour, 1, GL_RGBA32F, o.width, o.height);
  glCreateTextures(GL_TEXTURE_2D, 1, &distance);
  glTextureStorage2D(distance, 1, GL_R32F, o.width, o.height);
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, o.width, o.height);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, colour, 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, distance, 0);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("terrain framebuffer incomplete");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, both);
  glViewport(0, 0, o.width, o.height);

  // The host's depth convention.
  Frame f;
  f.width = o.width;
  f.height = o.height;
  f.farDepth = reverseZ ? 0.0 : 1.0;
  glClipControl(GL_LOWER_LEFT, reverseZ ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
  glClearDepth(f.farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(reverseZ ? GL_GREATER : GL_LESS);
  const float clearColour[4] = {0.0f, 0.0f, 0.0f, 0.0f}, clearDistance[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, clearColour);
  glClearBufferfv(GL_COLOR, 1, clearDistance);
  glClear(GL_DEPTH_BUFFER_BIT);

  const Mat4 view = viewMatrix(o.yawDeg, o.pitchDeg);
  const Mat4 projection = projectionMatrix(o.horizontalFovDeg, double(o.width) / o.height, 10.0, 2.0 * o.terrainRadiusM, o.depth);
  const Mat4 viewProjection = multiply(projection, view);

  // The terrain.
  const Mesh mesh = terrain(sky, o);
  GLuint vao = 0, vbo = 0, ibo = 0;
  glCreateVertexArrays(1, &vao);
  glCreateBuffers(1, &vbo);
  glCreateBuffers(1, &ibo);
  glNamedBufferStorage(vbo, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(), 0);
  glNamedBufferStorage(ibo, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(unsigned)), mesh.indices.data(), 0);
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, 7 * sizeof(float));
  glVertexArrayElementBuffer(vao, ibo);
  const GLuint sizes[3] = {3, 3, 1}, offsets[3] = {0, 3, 6};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, static_cast<GLint>(sizes[a]), GL_FLOAT, GL_FALSE, offsets[a] * sizeof(float));
    glVertexArrayAttribBinding(vao, a, 0);
  }
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertex);
  const GLuint fs =
      compile(GL_FRAGMENT_SHADER, "#version 450 core\n" + skyig::SkyDraw::aerialPerspectiveGlsl() + kFragment);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  // skyig's tables on texture units 0 to 5 (this host binds no textures of its own).
  skyDraw.bindAerialPerspective(sky, program, 0);
  glUseProgram(program);
  glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), 1, GL_FALSE, viewProjection.data());
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);

  f.terrainOnly = readRgb(GL_COLOR_ATTACHMENT0, o.width, o.height);
  f.distanceM.resize(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height));
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, o.width, o.height, GL_RED, GL_FLOAT, f.distanceM.data());
  f.depth.resize(f.distanceM.size());
  glReadPixels(0, 0, o.width, o.height, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());

  // The sky behind it, in the same linear light: into colour attachment 0 only.
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  skyDraw.draw(sky, view.data(), projection.data(), skyig::Viewport{0, 0, o.width, o.height},
               skyig::DrawOptions{o.depth, skyig::Output::LinearLight});
  f.final = readRgb(GL_COLOR_ATTACHMENT0, o.width, o.height);

  glDeleteProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  glDeleteVertexArrays(1, &vao);
  glDeleteBuffers(1, &vbo);
  glDeleteBuffers(1, &ibo);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  const GLuint textures[3] = {colour, distance, depth};
  glDeleteTextures(3, textures);
  return f;
}

HeadlessContext::HeadlessContext() {
  EGLDisplay display = EGL_NO_DISPLAY;
  // Mesa's surfaceless platform (no display server), else the default display.
  const auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (getPlatformDisplay) display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr))
      throw std::runtime_error("no EGL display (is libegl-mesa0 installed?)");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("eglBindAPI(EGL_OPENGL_API) failed");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, nullptr, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) throw std::runtime_error("eglCreateContext(OpenGL 4.5 core) failed");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw std::runtime_error("eglMakeCurrent (surfaceless) failed");
  display_ = display;
  context_ = context;
}

HeadlessContext::~HeadlessContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
}

skyig::GlProcAddress HeadlessContext::procAddress() {
  return [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
}

std::vector<unsigned char> toneMap(const std::vector<float>& rgb, double adaptationLuminance) {
  std::vector<unsigned char> out(rgb.size());
  const double exposure = 0.18 / std::max(adaptationLuminance, 1e-9);
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    const double x = std::max(0.0, double(rgb[i]) * exposure);
    const double linear = x / (1.0 + x);
    const double srgb = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    out[i] = static_cast<unsigned char>(std::lround(std::clamp(srgb, 0.0, 1.0) * 255.0));
  }
  return out;
}

}  // namespace terrain_host
