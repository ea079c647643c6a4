#pragma once
// Checks that a call throws InvalidInput whose message contains every given part (the unit
// tests' form of "a clear error that names the object and the value").

#include "core/errors.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace froth::test {

/// Checks that f throws an Error of type E whose message contains every part.
template <class E>
void expect_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no exception of the expected type thrown";
    } catch (const E& e) {
        const std::string msg = e.what();
        for (const std::string& s : parts)
            EXPECT_NE(msg.find(s), std::string::npos) << "'" << msg << "' lacks '" << s << "'";
    }
}

inline void expect_invalid(const std::function<void()>& f, const std::vector<std::string>& parts) {
    expect_error<InvalidInput>(f, parts);
}

} // namespace froth::test
