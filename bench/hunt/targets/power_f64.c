/* Target (2): evaluation through the power basis in f64. The patch is expanded once, exactly
 * (integer control values, integer coefficients below 2^53), to monomials in u and v with
 * w = 1 - u - v substituted:
 *   f(u, v) = sum over i + j <= n of a_ij u^i v^j,
 *   a_ij = sum over c_pqk, a + b <= k with p + a = i, q + b = j of
 *          c_pqk * n!/(p! q! k!) * k!/(a! b! (k-a-b)!) * (-1)^(a+b);
 * then each row is evaluated by Horner in v for p_i(v) = sum_j a_ij v^j, and Horner in u over the
 * p_i. The row's w is not used. Usage: power_f64 PATCH.net */
#include "proto.h"

static struct net net;
static double a[MAX_DEGREE + 1][MAX_DEGREE + 1][MAX_DIM];

static void eval(const double *lam, double *out) {
    double u = lam[0], v = lam[1];
    int n = net.n;
    for (int e = 0; e < net.d; e++) {
        double s = 0.0;
        for (int i = n; i >= 0; i--) {
            double p = a[i][n - i][e];
            for (int j = n - i - 1; j >= 0; j--) p = p * v + a[i][j][e];
            s = i == n ? p : s * u + p;
        }
        out[e] = s;
    }
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: power_f64 PATCH.net");
    read_net(argv[1], &net);
    double fact[MAX_DEGREE + 1] = {1};
    for (int i = 1; i <= MAX_DEGREE; i++) fact[i] = fact[i - 1] * i;
    int n = net.n;
    for (int r = 0; r < net.count; r++) {
        int p = net.idx[r][0], q = net.idx[r][1], k = net.idx[r][2];
        double m = fact[n] / (fact[p] * fact[q] * fact[k]);
        for (int x = 0; x <= k; x++)
            for (int y = 0; x + y <= k; y++) {
                double t = m * fact[k] / (fact[x] * fact[y] * fact[k - x - y]);
                if ((x + y) % 2) t = -t;
                for (int e = 0; e < net.d; e++) a[p + x][q + y][e] += t * net.c[r][e];
            }
    }
    serve(3, net.d, eval);
    return 0;
}
