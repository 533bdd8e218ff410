// Plot writer: the PNG has the requested size, and a known line lands on the pixels the axes say it should.
#include "support/plot.h"

#include <gtest/gtest.h>

#include <FreeImage.h>

#include <cmath>
#include <filesystem>

#include <unistd.h>

namespace trazo {
namespace {

PlotSpec lineSpec() {
    PlotSpec spec;
    spec.width = 640;
    spec.height = 480;
    spec.title = "Test plot";
    spec.xLabel = "time (s)";
    spec.yLabel = "relative error";
    PlotSeries s;
    s.label = "y = 0.1/sqrt(x)";
    s.color = Vec3(0.0f, 0.0f, 1.0f);
    s.markers = false;
    for (double x : {0.01, 100.0}) {
        s.x.push_back(x);
        s.y.push_back(0.1 / std::sqrt(x));
    }
    spec.series.push_back(s);
    return spec;
}

bool isBlue(const Vec3& c) { return c.z > 0.9f && c.x < 0.45f && c.y < 0.45f; }

TEST(Plot, AxesFitWholeDecades) {
    const PlotImage img = drawPlot(lineSpec());
    EXPECT_DOUBLE_EQ(img.frame.x0, -2.0);
    EXPECT_DOUBLE_EQ(img.frame.x1, 2.0);
    EXPECT_DOUBLE_EQ(img.frame.y0, -2.0);  // 0.1/sqrt(100) = 0.01
    EXPECT_DOUBLE_EQ(img.frame.y1, 0.0);   // 0.1/sqrt(0.01) = 1
    EXPECT_EQ(decadeLabel(-2), "0.01");
    EXPECT_EQ(decadeLabel(3), "1000");
    EXPECT_EQ(decadeLabel(-5), "1e-5");
}

TEST(Plot, KnownLineLandsOnItsPixels) {
    const PlotImage img = drawPlot(lineSpec());
    ASSERT_EQ(img.width, 640);
    ASSERT_EQ(img.height, 480);
    const PlotFrame& f = img.frame;
    // On log–log axes y = 0.1 x^-1/2 is a straight line: sample it and find blue at each point, white-ish
    // well away from it (avoiding the legend box in the top right).
    int onLine = 0, tested = 0;
    for (double lx = -1.8; lx <= 1.0; lx += 0.2) {
        const double x = std::pow(10.0, lx), y = 0.1 / std::sqrt(x);
        const int px = (int)std::lround(f.pixelX(x)), py = (int)std::lround(f.pixelY(y));
        ASSERT_GT(px, f.left);
        ASSERT_LT(py, f.bottom);
        ++tested;
        if (isBlue(img.at(px, py))) ++onLine;
        const int far = py + 60 < f.bottom - 2 ? py + 60 : py - 60;
        EXPECT_FALSE(isBlue(img.at(px, far))) << "blue far from the line at " << px << "," << far;
    }
    EXPECT_EQ(onLine, tested);
    // The line is 2 px wide: perpendicular to it (slope −1/2 in decades, nearly so in pixels here) the
    // blue run is short.
    const int px = (int)std::lround(f.pixelX(1.0)), py = (int)std::lround(f.pixelY(0.1));
    int run = 0;
    for (int y = py - 10; y <= py + 10; ++y) run += isBlue(img.at(px, y)) ? 1 : 0;
    EXPECT_GE(run, 1);
    EXPECT_LE(run, 5);
}

TEST(Plot, WritesAPngOfTheRequestedSize) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("trazo_plot_test_" + std::to_string(::getpid()) + ".png")).string();
    std::string error;
    ASSERT_TRUE(writePlot(path, lineSpec(), error)) << error;
    FIBITMAP* bmp = FreeImage_Load(FIF_PNG, path.c_str(), 0);
    ASSERT_NE(bmp, nullptr);
    EXPECT_EQ(FreeImage_GetWidth(bmp), 640u);
    EXPECT_EQ(FreeImage_GetHeight(bmp), 480u);
    FreeImage_Unload(bmp);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace trazo
