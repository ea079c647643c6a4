#pragma once
// Checks that a call throws InvalidInput whose message contains every given part (the unit
// tests' form of "a clear error that names the object and the value").

#include "core/errors.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace froth::test {

inline void expect_invalid(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no InvalidInput thrown";
    } catch (const InvalidInput& e) {
        const std::string msg = e.what();
        for (const std::string& s : parts)
            EXPECT_NE(msg.find(s), std::string::npos) << "'" << msg << "' lacks '" << s << "'";
    }
}

} // namespace froth::test
