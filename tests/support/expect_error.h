// boreas tests: the check that a call fails with a given error status and message.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>

#include "errors.h"

namespace boreas::test {

// Runs f and expects an impl::Error with `status` whose message holds every piece.
inline void expect_error(const std::function<void()>& f, boreas_status status,
                         std::initializer_list<std::string> pieces) {
  try {
    f();
  } catch (const impl::Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.status(), status) << what;
    for (const std::string& p : pieces) {
      EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
    }
    return;
  }
  ADD_FAILURE() << "no error thrown";
}

}  // namespace boreas::test
