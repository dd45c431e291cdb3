// boreas: checks on the caller's buffers.
#include "runtime/caller_buffers.h"

#include <string>

#include "errors.h"

namespace boreas::impl {

void check_buffer_holds(const cl::Buffer& buffer, size_t first, size_t records, size_t record_bytes,
                        const char* what) {
  if (buffer() == nullptr) fail_argument(std::string(what) + " buffer is NULL");
  size_t size = 0;
  BOREAS_CL_CHECK(buffer.getInfo(CL_MEM_SIZE, &size));
  const size_t need = (first + records) * record_bytes;
  if (first > size || need > size)
    fail_argument(std::string(what) + " buffer holds " + std::to_string(size) + " bytes; records " +
                  std::to_string(first) + ".." + std::to_string(first + records) + " need " +
                  std::to_string(need));
}

}  // namespace boreas::impl
