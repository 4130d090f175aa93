/* judge.c: judge a hand-written C de Casteljau of a quadratic Bézier triangle against tribez's
 * exact values, the way a C test suite would. Build and run: make -C examples/c run (docs/c.md).
 * Exit status: 0 when every row is within the tolerance, 1 otherwise, 2 on an error. */
#include <stdio.h>
#include <stdlib.h>

#include <tribez.h>

/* Finn's triangle: control points 200, 110, 020, 101, 011, 002 (tribez's canonical order) */
static const double NET[6][3] = {{0, 0, 0}, {1, 0, 2}, {0, 2, 0}, {0, 1, 0}, {1, 1, 1}, {0, 2, 1}};

/* de Casteljau, degree 2: two levels of u b_(i+1)jk + v b_i(j+1)k + w b_ij(k+1) */
static void eval(double u, double v, double w, double out[3]) {
    for (int c = 0; c < 3; c++) {
        double b100 = u * NET[0][c] + v * NET[1][c] + w * NET[3][c];
        double b010 = u * NET[1][c] + v * NET[2][c] + w * NET[4][c];
        double b001 = u * NET[3][c] + v * NET[4][c] + w * NET[5][c];
        out[c] = u * b100 + v * b010 + w * b001;
    }
}

static int fail(tribez_error *err) {
    fprintf(stderr, "judge: %s\n", tribez_error_message(err));
    tribez_error_free(err);
    return 2;
}

int main(void) {
    tribez_error *err = NULL;
    tribez_patch *patch = tribez_patch_from_f64(2, 2, 3, &NET[0][0], &err);
    if (!patch) return fail(err);

    /* the exact value at (1/2, 1/3, 1/6) */
    const char *point[3] = {"1/2", "1/3", "1/6"};
    char **exact = NULL;
    size_t n = 0;
    if (tribez_eval_exact(patch, point, 3, &exact, &n, &err) != TRIBEZ_OK) return fail(err);
    printf("exact at (1/2, 1/3, 1/6): (%s, %s, %s)\n", exact[0], exact[1], exact[2]);
    tribez_strings_free(exact, n);

    /* 1000 points on a grid-like walk over the triangle, and what eval() computes there */
    enum { ROWS = 1000 };
    static double points[ROWS][3], values[ROWS][3];
    for (int r = 0; r < ROWS; r++) {
        double u = (r % 37) / 37.0, v = (1 - u) * ((r / 37) % 29) / 29.0;
        points[r][0] = u;
        points[r][1] = v;
        points[r][2] = 1 - u - v;
        eval(points[r][0], points[r][1], points[r][2], values[r]);
    }

    /* judged as `tribez check --tolerance bound` would: within de Casteljau's a-priori bound */
    tribez_report *report = NULL;
    if (tribez_check_f64(patch, &points[0][0], &values[0][0], ROWS, "bound", NULL, &report, &err)
        != TRIBEZ_OK)
        return fail(err);
    printf("bound: %llu passed, %llu failed\n", (unsigned long long)tribez_report_passed(report),
           (unsigned long long)tribez_report_failed(report));
    int ok = tribez_report_ok(report);
    tribez_report_free(report);

    /* and against the strictest tolerance: how many rows are not correctly rounded */
    if (tribez_check_f64(patch, &points[0][0], &values[0][0], ROWS, "correctly_rounded", NULL,
                         &report, &err) != TRIBEZ_OK)
        return fail(err);
    size_t worst = 0;
    tribez_report_worst_row(report, &worst);
    printf("correctly_rounded: %llu passed, %llu failed; the worst row is %zu, %.3g ulp\n",
           (unsigned long long)tribez_report_passed(report),
           (unsigned long long)tribez_report_failed(report), worst, tribez_report_max_ulps(report));
    tribez_report_free(report);
    tribez_patch_free(patch);
    return ok ? 0 : 1;
}
