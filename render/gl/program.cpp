// boreas render: GLSL programs (program.h).
#include "gl/program.h"

#include <epoxy/gl.h>

#include "gl/shader_source.h"

namespace boreas::render {
namespace {

std::string info_log(GLuint object, bool program) {
  GLint length = 0;
  if (program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(length > 0 ? length : 1), '\0');
  if (program)
    glGetProgramInfoLog(object, GLsizei(log.size()), nullptr, log.data());
  else
    glGetShaderInfoLog(object, GLsizei(log.size()), nullptr, log.data());
  return log.c_str();
}

}  // namespace

Program::Program(const std::vector<ShaderStage>& stages, const std::string& defines) {
  id_ = glCreateProgram();
  std::vector<GLuint> shaders;
  std::string names;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const ShaderStage& stage : stages) {
    // The #line after the prelude makes the driver's line numbers those of the file.
    const std::string text = "#version 450 core\n" + defines + "#line 1\n" + shader_source(stage.file);
    GLuint s = glCreateShader(stage.type);
    shaders.push_back(s);
    const char* src = text.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = info_log(s, false);
      cleanup();
      glDeleteProgram(id_);
      throw ShaderError("shader " + stage.file + " does not compile:\n" + log);
    }
    glAttachShader(id_, s);
    names += (names.empty() ? "" : " + ") + stage.file;
  }
  glLinkProgram(id_);
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, true);
    glDeleteProgram(id_);
    throw ShaderError("program " + names + " does not link:\n" + log);
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept : id_(other.id_) { other.id_ = 0; }

void Program::use() const { glUseProgram(id_); }

int Program::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

}  // namespace boreas::render
