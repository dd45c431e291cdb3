// boreas render: creating and deleting OpenGL objects for GlObject.
#include "gl/gl_objects.h"

#include <epoxy/gl.h>

namespace boreas::render {

namespace {
void delete_buffer(unsigned id) { glDeleteBuffers(1, &id); }
void delete_texture(unsigned id) { glDeleteTextures(1, &id); }
void delete_framebuffer(unsigned id) { glDeleteFramebuffers(1, &id); }
void delete_vertex_array(unsigned id) { glDeleteVertexArrays(1, &id); }
}  // namespace

GlObject make_buffer() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return GlObject(id, delete_buffer);
}

GlObject make_texture(unsigned target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return GlObject(id, delete_texture);
}

GlObject make_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return GlObject(id, delete_framebuffer);
}

GlObject make_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return GlObject(id, delete_vertex_array);
}

}  // namespace boreas::render
