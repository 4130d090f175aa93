/* A tribez hunt target: Finn's quadratic (fixtures/finn_day30.toml) by de Casteljau in double. */
#include <stdio.h>

int main(void) {
    double u, v, w, c[6][3] = {{0, 0, 0}, {1, 0, 2}, {0, 2, 0}, {0, 1, 0}, {1, 1, 1}, {0, 2, 1}};
    while (scanf("%la,%la,%la", &u, &v, &w) == 3) {
        for (int k = 0; k < 3; k++) { /* 200 110 020 101 011 002 -> 100 010 001 -> 000 */
            double a = u * c[0][k] + v * c[1][k] + w * c[3][k], b = u * c[1][k] + v * c[2][k] + w * c[4][k];
            double d = u * c[3][k] + v * c[4][k] + w * c[5][k];
            printf("%a%c", u * a + v * b + w * d, k < 2 ? ',' : '\n');
        }
        fflush(stdout);
    }
    return 0;
}
