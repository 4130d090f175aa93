// test_decasteljau.cpp: a GoogleTest-style test suite judging the hand-written C++ de Casteljau
// (decasteljau.hpp) against tribez, as a C++ library would in its own tests. Built with
// GoogleTest when pkg-config finds gtest_main (make defines TRIBEZ_USE_GTEST), else with the
// small stand-in below (the same macros). Expected values: crates/tribez-capi/tests/derive.py
// (Python fractions, no tribez).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <tribez.h>

#include "decasteljau.hpp"

#ifdef TRIBEZ_USE_GTEST
#include <gtest/gtest.h>
#else
#include "minitest.hpp"
#endif

// not in tribez.h: a test-only entry point that panics inside tribez
extern "C" int tribez__panic_for_test(const char *message, int in_worker, tribez_error **err);

namespace {

// Finn's quadratic triangle in R^3, control points 200, 110, 020, 101, 011, 002
const double FINN[18] = {0, 0, 0, 1, 0, 2, 0, 2, 0, 0, 1, 0, 1, 1, 1, 0, 2, 1};

// Owning handles, so that a failed ASSERT leaks nothing.
struct Patch {
    tribez_patch *p = nullptr;
    explicit Patch(tribez_patch *p_) : p(p_) {}
    ~Patch() { tribez_patch_free(p); }
};
struct Report {
    tribez_report *r = nullptr;
    ~Report() { tribez_report_free(r); }
};
struct Error {
    tribez_error *e = nullptr;
    ~Error() { tribez_error_free(e); }
    std::string message() const { return e ? tribez_error_message(e) : "(no error)"; }
};
struct Text {
    char *s;
    explicit Text(char *s_) : s(s_) {}
    ~Text() { tribez_string_free(s); }
};

// Rows of random barycentric points (u, v, 1 - u - v) and what the implementation computes.
template <class T>
void rows(std::size_t count, std::uint64_t seed, std::vector<T> &points, std::vector<T> &values) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<T> net(FINN, FINN + 18);
    for (std::size_t r = 0; r < count; ++r) {
        T u = T(unit(rng)), v = T((1 - double(u)) * unit(rng)), w = T(1) - u - v;
        points.insert(points.end(), {u, v, w});
        auto p = example::de_casteljau<T>(2, 3, net.data(), u, v, w);
        values.insert(values.end(), p.begin(), p.end());
    }
}

}  // namespace

TEST(DeCasteljau, WithinItsErrorBound) {
    Error err;
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, &err.e));
    ASSERT_TRUE(finn.p != nullptr) << err.message();
    std::vector<double> points, values;
    rows<double>(2000, 1, points, values);
    Report rep;
    ASSERT_EQ(tribez_check_f64(finn.p, points.data(), values.data(), 2000, "bound", nullptr, &rep.r,
                               &err.e),
              TRIBEZ_OK)
        << err.message();
    EXPECT_TRUE(tribez_report_ok(rep.r)) << Text(tribez_report_text(rep.r)).s;
    EXPECT_EQ(tribez_report_passed(rep.r), 2000u);
    EXPECT_EQ(tribez_report_checked(rep.r), 2000u);
    // de Casteljau in doubles is off by a few ULPs at most here
    EXPECT_TRUE(tribez_report_max_ulps(rep.r) < 8.0) << tribez_report_max_ulps(rep.r);
}

TEST(DeCasteljau, NotAlwaysCorrectlyRounded) {
    // derive.py: at this point the double de Casteljau's x is one ULP below the correctly
    // rounded 0x1.772cc1cd2fd97p-3; y and z are correctly rounded
    const double point[3] = {0x1.4b9ad0f953a6ep-2, 0x1.a1c9fc3f7ecf9p-4, 0x1.25f957fb6652ap-1};
    const double cr[3] = {0x1.772cc1cd2fd97p-3, 0x1.2b4cff49b0316p+0, 0x1.286858af58595p-1};
    Error err;
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, &err.e));
    ASSERT_TRUE(finn.p != nullptr) << err.message();
    auto mine = example::de_casteljau<double>(2, 3, FINN, point[0], point[1], point[2]);
    EXPECT_EQ(mine[0], 0x1.772cc1cd2fd96p-3);
    double exact[3];
    ASSERT_EQ(tribez_eval_f64_correctly_rounded(finn.p, point, 3, exact, 3, &err.e), TRIBEZ_OK)
        << err.message();
    for (int c = 0; c < 3; ++c) EXPECT_EQ(exact[c], cr[c]) << "coordinate " << c;

    Report strict, loose;
    ASSERT_EQ(tribez_check_f64(finn.p, point, mine.data(), 1, "correctly_rounded", nullptr,
                               &strict.r, &err.e),
              TRIBEZ_OK);
    EXPECT_EQ(tribez_report_failed(strict.r), 1u);
    EXPECT_FALSE(tribez_report_ok(strict.r));
    std::size_t worst = 99;
    EXPECT_TRUE(tribez_report_worst_row(strict.r, &worst));
    EXPECT_EQ(worst, 0u);
    ASSERT_EQ(tribez_check_f64(finn.p, point, mine.data(), 1, "ulps=1", nullptr, &loose.r, &err.e),
              TRIBEZ_OK);
    EXPECT_TRUE(tribez_report_ok(loose.r));
}

TEST(DeCasteljau, SinglePrecision) {
    Error err;
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, &err.e));
    ASSERT_TRUE(finn.p != nullptr) << err.message();
    std::vector<float> points, values;
    rows<float>(500, 2, points, values);
    Report rep;
    ASSERT_EQ(tribez_check_f32(finn.p, points.data(), values.data(), 500, "bound", nullptr, &rep.r,
                               &err.e),
              TRIBEZ_OK)
        << err.message();
    EXPECT_TRUE(tribez_report_ok(rep.r)) << Text(tribez_report_text(rep.r)).s;
    Text text(tribez_report_text(rep.r));
    EXPECT_TRUE(std::strstr(text.s, "each number the nearest f32") != nullptr) << text.s;
}

TEST(DeCasteljau, ABugIsCaught) {
    // the weights of v and w swapped: a plausible bug, far beyond any tolerance
    Error err;
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, &err.e));
    ASSERT_TRUE(finn.p != nullptr);
    std::vector<double> points, values;
    rows<double>(100, 3, points, values);
    for (std::size_t r = 0; r < 100; ++r) {
        auto p = example::de_casteljau<double>(2, 3, FINN, points[3 * r], points[3 * r + 2],
                                               points[3 * r + 1]);
        std::copy(p.begin(), p.end(), values.begin() + 3 * r);
    }
    Report rep;
    ASSERT_EQ(tribez_check_f64(finn.p, points.data(), values.data(), 100, "ulps=4", nullptr,
                               &rep.r, &err.e),
              TRIBEZ_OK);
    EXPECT_FALSE(tribez_report_ok(rep.r));
    EXPECT_TRUE(tribez_report_failed(rep.r) > 90u) << tribez_report_failed(rep.r);
    Text json(tribez_report_json(rep.r));
    EXPECT_TRUE(std::strstr(json.s, "\"failures\": [") != nullptr);
}

TEST(DeCasteljau, PartsMergeIntoTheWhole) {
    Error err;
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, &err.e));
    ASSERT_TRUE(finn.p != nullptr);
    std::vector<double> points, values;
    rows<double>(300, 4, points, values);
    tribez_check_options whole_opts{}, b_opts{};
    b_opts.first_row = 120;
    Report whole, a, b;
    ASSERT_EQ(tribez_check_f64(finn.p, points.data(), values.data(), 300, "correctly_rounded",
                               &whole_opts, &whole.r, &err.e),
              TRIBEZ_OK);
    ASSERT_EQ(tribez_check_f64(finn.p, points.data(), values.data(), 120, "correctly_rounded",
                               nullptr, &a.r, &err.e),
              TRIBEZ_OK);
    ASSERT_EQ(tribez_check_f64(finn.p, points.data() + 360, values.data() + 360, 180,
                               "correctly_rounded", &b_opts, &b.r, &err.e),
              TRIBEZ_OK);
    ASSERT_EQ(tribez_report_merge(a.r, b.r, &err.e), TRIBEZ_OK) << err.message();
    Text t1(tribez_report_text(a.r)), t2(tribez_report_text(whole.r));
    EXPECT_STREQ(t1.s, t2.s);
    Text j1(tribez_report_json(a.r)), j2(tribez_report_json(whole.r));
    EXPECT_STREQ(j1.s, j2.s);
    // merging b again would count its rows twice
    EXPECT_EQ(tribez_report_merge(a.r, b.r, &err.e), TRIBEZ_ERROR_INPUT);
    EXPECT_TRUE(err.message().find("both reports have row 120") != std::string::npos)
        << err.message();
}

// A hunt target: the C++ de Casteljau, with ctx != nullptr planting a fault where u < 2^-10.
extern "C" void finn_target(void *ctx, const double *in, std::size_t rows, double *out) {
    for (std::size_t r = 0; r < rows; ++r) {
        auto p = example::de_casteljau<double>(2, 3, FINN, in[3 * r], in[3 * r + 1], in[3 * r + 2]);
        if (ctx != nullptr && in[3 * r] < 1.0 / 1024) p[0] *= 1 + 1.0 / 1048576;
        std::copy(p.begin(), p.end(), out + 3 * r);
    }
}

TEST(Hunt, FindsAPlantedFault) {
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, nullptr));
    ASSERT_TRUE(finn.p != nullptr);
    tribez_hunt_options opts{};
    opts.budget = 3000;
    Error err;
    tribez_hunt_report *sound = nullptr, *faulty = nullptr;
    ASSERT_EQ(tribez_hunt(finn.p, finn_target, nullptr, "bound", &opts, &sound, &err.e), TRIBEZ_OK)
        << err.message();
    EXPECT_EQ(tribez_hunt_report_broke(sound), 0u);
    EXPECT_EQ(tribez_hunt_report_evaluated(sound), 3000u);
    int planted = 1;
    ASSERT_EQ(tribez_hunt(finn.p, finn_target, &planted, "bound", &opts, &faulty, &err.e), TRIBEZ_OK);
    double input[3], claimed[3];
    double ulps = tribez_hunt_report_worst(faulty, 0, input, claimed);
    EXPECT_TRUE(ulps > 1e6) << ulps;
    EXPECT_TRUE(input[0] < 1.0 / 1024) << input[0];
    tribez_hunt_report_free(sound);
    tribez_hunt_report_free(faulty);
}

TEST(Errors, OneLineMessages) {
    Error err;
    EXPECT_TRUE(tribez_patch_from_file("no/such/patch.toml", &err.e) == nullptr);
    EXPECT_EQ(tribez_error_code(err.e), TRIBEZ_ERROR_INPUT);
    EXPECT_TRUE(err.message().rfind("no/such/patch.toml", 0) == 0) << err.message();
    EXPECT_TRUE(err.message().find('\n') == std::string::npos);
    tribez_error_free(err.e);
    err.e = nullptr;

    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, nullptr));
    ASSERT_TRUE(finn.p != nullptr);
    const double p[3] = {0.5, 0.25, 0.25}, v[3] = {0.375, 0.625, 0.6875};
    Report rep;
    EXPECT_EQ(tribez_check_f64(finn.p, p, v, 1, "ulps=-1", nullptr, &rep.r, &err.e),
              TRIBEZ_ERROR_INPUT);
    EXPECT_TRUE(err.message().rfind("tolerance: ", 0) == 0) << err.message();
    EXPECT_TRUE(rep.r == nullptr);
    tribez_error_free(err.e);
    err.e = nullptr;
    EXPECT_EQ(tribez_check_f64(nullptr, p, v, 1, "exact", nullptr, &rep.r, &err.e),
              TRIBEZ_ERROR_NULL);
    EXPECT_EQ(err.message(), std::string("patch: NULL pointer"));
    // NULL err: the status alone
    EXPECT_EQ(tribez_check_f64(finn.p, p, v, 0, "exact", nullptr, &rep.r, nullptr),
              TRIBEZ_ERROR_INPUT);
    // NaN in a control point
    const double bad[18] = {0, 0, 0, 1, 0, 2, 0, 2, 0, 0, NAN, 0, 1, 1, 1, 0, 2, 1};
    EXPECT_TRUE(tribez_patch_from_f64(2, 2, 3, bad, nullptr) == nullptr);
    // a NaN result is a failed row, not an error
    const double nan_values[3] = {NAN, 0.625, 0.6875};
    ASSERT_EQ(tribez_check_f64(finn.p, p, nan_values, 1, "exact", nullptr, &rep.r, nullptr),
              TRIBEZ_OK);
    EXPECT_EQ(tribez_report_failed(rep.r), 1u);
    EXPECT_TRUE(std::isnan(tribez_report_max_ulps(rep.r)));
}

TEST(Errors, APanicIsAnError) {
    for (int in_worker = 0; in_worker < 2; ++in_worker) {
        Error err;
        EXPECT_EQ(tribez__panic_for_test("on purpose", in_worker, &err.e), TRIBEZ_ERROR_INTERNAL);
        EXPECT_TRUE(err.message().find("internal error in tribez") != std::string::npos);
        EXPECT_TRUE(err.message().find("on purpose") != std::string::npos) << err.message();
    }
}

TEST(Threads, DistinctHandlesAndASharedPatch) {
    Patch finn(tribez_patch_from_f64(2, 2, 3, FINN, nullptr));
    ASSERT_TRUE(finn.p != nullptr);
    std::vector<double> points, values;
    rows<double>(1000, 5, points, values);
    std::vector<std::uint64_t> passed(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            tribez_report *r = nullptr;
            if (tribez_check_f64(finn.p, points.data(), values.data(), 1000, "ulps=4", nullptr,
                                 &r, nullptr) == TRIBEZ_OK)
                passed[t] = tribez_report_passed(r);
            tribez_report_free(r);
        });
    }
    for (auto &t : threads) t.join();
    for (int t = 0; t < 4; ++t) EXPECT_EQ(passed[t], 1000u) << "thread " << t;
}

#ifndef TRIBEZ_USE_GTEST
int main() { return minitest::run_all(); }
#endif
