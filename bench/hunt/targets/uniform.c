/* N uniform random points of the triangle, one row per line as the hunt writes them: the
 * barycentric coordinates e_i / (e_0 + e_1 + e_2) with e_i = -ln(1 - U_i) (U_i uniform in [0, 1)
 * from SplitMix64 seeded with SEED), rounded to the precision, the largest then set to the float
 * nearest 1 - (the other two) as the hunt does; comma-separated hex floats.
 * Usage: uniform SEED N f64|f32 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t state;
static uint64_t next(void) {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double unit(void) { return (double)(next() >> 11) * 0x1p-53; }

int main(int argc, char **argv) {
    if (argc != 4 || (strcmp(argv[3], "f64") && strcmp(argv[3], "f32"))) {
        fprintf(stderr, "usage: uniform SEED N f64|f32\n");
        return 2;
    }
    state = strtoull(argv[1], NULL, 10) ^ 0x756E69666F726Dull;
    long n = atol(argv[2]);
    int f32 = !strcmp(argv[3], "f32");
    for (long r = 0; r < n; r++) {
        double l[3], s = 0;
        for (int i = 0; i < 3; i++) s += (l[i] = -log(1.0 - unit()));
        int big = 0;
        for (int i = 0; i < 3; i++) {
            l[i] /= s;
            if (f32) l[i] = (double)(float)l[i];
            if (l[i] > l[big]) big = i;
        }
        double others = 0;
        for (int i = 0; i < 3; i++)
            if (i != big) others += l[i];
        l[big] = 1.0 - others;
        if (f32) l[big] = (double)(float)l[big];
        printf("%a,%a,%a\n", l[0], l[1], l[2]);
    }
    return 0;
}
