// libFuzzer harness for the records reader (harness/record.cpp readRecord, through
// report/regression_check.cpp) behind the strict JSON reader: what `check` reads of a
// metrics.json and `merge` of a shard's records.json. A file that reads is then compared
// with itself and reported, as `check` does. Any input must end there or in an InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/report/regression_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto records = testbed::parseCheckRecords(testbed::parseJsonInput(text, "metrics.json"), "metrics.json");
    const testbed::CheckReport report = records.empty()
                                            ? testbed::CheckReport{}
                                            : testbed::compareRecords(records, records, testbed::CheckTolerances{});
    // A file compared with itself has no regression.
    if (report.failed()) std::abort();
    testbed::checkReportMarkdown(report, testbed::CheckTolerances{});
  } catch (const testbed::InputError&) {
  }
  return 0;
}
