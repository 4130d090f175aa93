// minitest.hpp: the few GoogleTest macros test_decasteljau.cpp uses, for machines without
// GoogleTest (TEST, EXPECT_*/ASSERT_* with << messages). Prints one line per failure and the
// summary "N passed, N failed"; run_all() returns 0 when every test passed.
#pragma once

#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace minitest {

struct Test {
    const char *name;
    std::function<void()> body;
};
inline std::vector<Test> &tests() {
    static std::vector<Test> all;
    return all;
}
inline bool &current_failed() {
    static bool failed = false;
    return failed;
}
struct Register {
    Register(const char *name, std::function<void()> body) { tests().push_back({name, body}); }
};
// A failed expectation: collects the << message, prints it when the statement ends.
struct Failure {
    std::ostringstream msg;
    Failure(const char *file, int line, const char *what) {
        msg << file << ":" << line << ": failed: " << what << " ";
    }
    Failure(const Failure &) = delete;
    template <class T>
    Failure &operator<<(const T &x) {
        msg << x;
        return *this;
    }
    ~Failure() {
        current_failed() = true;
        std::printf("%s\n", msg.str().c_str());
    }
};
struct Void {
    void operator=(const Failure &) {}
};
inline int run_all() {
    int passed = 0, failed = 0;
    for (auto &t : tests()) {
        current_failed() = false;
        t.body();
        std::printf("[ %s ] %s\n", current_failed() ? "FAILED" : "    OK", t.name);
        (current_failed() ? failed : passed)++;
    }
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}

}  // namespace minitest

#define TEST(suite, name)                                                               \
    static void suite##_##name();                                                       \
    static minitest::Register suite##_##name##_reg(#suite "." #name, suite##_##name);   \
    static void suite##_##name()

#define MT_CHECK(cond, text, fatal_return) \
    if (cond)                              \
        ;                                  \
    else                                   \
        fatal_return minitest::Void() = minitest::Failure(__FILE__, __LINE__, text)

#define EXPECT_TRUE(c) MT_CHECK((c), #c, )
#define EXPECT_FALSE(c) MT_CHECK(!(c), "!(" #c ")", )
#define EXPECT_EQ(a, b) MT_CHECK((a) == (b), #a " == " #b, )
#define EXPECT_STREQ(a, b) MT_CHECK(std::strcmp((a), (b)) == 0, #a " equals " #b, )
#define ASSERT_TRUE(c) MT_CHECK((c), #c, return)
#define ASSERT_EQ(a, b) MT_CHECK((a) == (b), #a " == " #b, return)
