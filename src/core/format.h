#pragma once
/// Numbers in error messages: "%.6g" (std::to_string prints 1e-9 as "0.000000").

#include <cmath>
#include <cstdio>
#include <string>

namespace froth {

inline std::string fmt(double x) {
    if (std::isnan(x)) return "nan"; // printf may say "-nan"
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

} // namespace froth
