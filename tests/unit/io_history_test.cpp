// History files of an evolution: the CSV reads back exactly, the SVG plots every row.
#include "core/errors.h"
#include "io/history.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace froth {
namespace {

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<HistoryRow> decaying_rows(int n) {
    std::vector<HistoryRow> rows;
    for (int k = 0; k < n; ++k)
        rows.push_back({0.01 * k, k ? 0.01 : 0.0, 15.0 + std::exp(-0.3 * k), 1e-4 * k,
                        {2.0 + 1e-3 * k, 1.0 / 3}});
    return rows;
}

TEST(History, CsvReadsBackExactly) {
    const std::string path = testing::TempDir() + "/froth_history/run.csv";
    const auto rows = decaying_rows(7);
    write_history_csv(path, rows);
    std::istringstream in(read(path));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t,tau,energy,volume_loss,V1,V2");
    for (const HistoryRow& r : rows) {
        ASSERT_TRUE(std::getline(in, line));
        double t, tau, e, loss, v1, v2;
        char c;
        std::istringstream fields(line);
        fields >> t >> c >> tau >> c >> e >> c >> loss >> c >> v1 >> c >> v2;
        EXPECT_EQ(t, r.t);
        EXPECT_EQ(tau, r.tau);
        EXPECT_EQ(e, r.energy);
        EXPECT_EQ(loss, r.volume_loss);
        EXPECT_EQ(v1, r.volumes[0]);
        EXPECT_EQ(v2, r.volumes[1]);
    }
    EXPECT_FALSE(std::getline(in, line));
}

TEST(History, SvgHasOnePointPerRowAndTheTitle) {
    const std::string path = testing::TempDir() + "/froth_history/run.svg";
    write_history_svg(path, decaying_rows(9), "a <b> & c");
    const std::string svg = read(path);
    EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
    const auto start = svg.find("points=\"");
    ASSERT_NE(start, std::string::npos);
    const std::string points = svg.substr(start + 8, svg.find('"', start + 8) - start - 8);
    EXPECT_EQ(std::count(points.begin(), points.end(), ','), 9);
}

TEST(History, EmptyHistoryAndBadPathsAreErrors) {
    EXPECT_THROW(write_history_csv(testing::TempDir() + "/x.csv", {}), InvalidInput);
    EXPECT_THROW(write_history_svg("/proc/froth/x.svg", decaying_rows(2), "t"), IoError);
}

} // namespace
} // namespace froth
