// boreas: checks on the caller's buffers.
#include "runtime/caller_buffers.h"

#include <algorithm>
#include <numeric>
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

void check_disjoint(const std::vector<CallerRange>& ranges, const char* what) {
  std::vector<size_t> order(ranges.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return ranges[a].first < ranges[b].first; });
  size_t last = ranges.size();  // the range reaching furthest so far, among the non-empty
  for (size_t k : order) {
    if (ranges[k].count == 0) continue;
    if (last < ranges.size() && ranges[last].first + ranges[last].count > ranges[k].first) {
      const auto item = [&](size_t i) {
        return std::string(what) + "[" + std::to_string(i) + "] (records " +
               std::to_string(ranges[i].first) + ".." +
               std::to_string(ranges[i].first + ranges[i].count) + ")";
      };
      fail_argument(item(std::min(last, k)) + " and " + item(std::max(last, k)) + " overlap");
    }
    if (last == ranges.size() ||
        ranges[k].first + ranges[k].count > ranges[last].first + ranges[last].count)
      last = k;
  }
}

}  // namespace boreas::impl
