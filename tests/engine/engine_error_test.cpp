// Embree errors reach callers as EngineError: the real callback path (a deliberately invalid
// Embree call on a fresh device) and the code -> message conversion.
#include "dayphoton/engine/engine_error.h"

#include <gtest/gtest.h>

#include <string>

namespace dayphoton::engine {
namespace {

TEST(EngineError, EmbreeCallbackErrorBecomesEngineError) {
  try {
    detail::provoke_embree_error();
    FAIL() << "no exception";
  } catch (const EngineError& e) {
    // rtcNewGeometry with an unknown type: Embree 3.13.5 reports RTC_ERROR_UNKNOWN with the
    // message "invalid geometry type" (checked against the installed library).
    EXPECT_NE(e.embree_code(), 0) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("Embree error RTC_ERROR_", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("invalid geometry type"), std::string::npos) << e.what();
  }
}

TEST(EngineError, ConversionNamesTheCode) {
  EXPECT_EQ(std::string(embree_error(2, "invalid argument").what()),
            "Embree error RTC_ERROR_INVALID_ARGUMENT: invalid argument");
  EXPECT_EQ(embree_error(4, "x").embree_code(), 4);
  EXPECT_EQ(embree_error_name(0), "RTC_ERROR_NONE");
  EXPECT_EQ(embree_error_name(1), "RTC_ERROR_UNKNOWN");
  EXPECT_EQ(embree_error_name(3), "RTC_ERROR_INVALID_OPERATION");
  EXPECT_EQ(embree_error_name(4), "RTC_ERROR_OUT_OF_MEMORY");
  EXPECT_EQ(embree_error_name(5), "RTC_ERROR_UNSUPPORTED_CPU");
  EXPECT_EQ(embree_error_name(6), "RTC_ERROR_CANCELLED");
  EXPECT_EQ(embree_error_name(99), "RTC_ERROR_99");
  EXPECT_EQ(std::string(embree_error(1, "").what()), "Embree error RTC_ERROR_UNKNOWN: (no message)");
}

TEST(EngineError, EmbreeVersionIsThree) {
  const std::string v = embree_version();
  EXPECT_EQ(v.rfind("3.", 0), 0u) << v;
}

}  // namespace
}  // namespace dayphoton::engine
