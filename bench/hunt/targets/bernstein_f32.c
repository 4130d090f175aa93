/* Target (1): the direct Bernstein sum in f32,
 *   f(u, v, w) = sum over i + j + k = n of c_ijk * (n! / (i! j! k!)) * u^i * v^j * w^k,
 * every operation in binary32: the powers by repeated multiplication, each term as
 * ((coefficient * c) * u^i) * v^j * w^k, the terms added in the canonical order.
 * Usage: bernstein_f32 PATCH.net */
#include "proto.h"

static struct net net;
static float coef[MAX_POINTS][MAX_DIM];

static void eval(const double *lam, double *out) {
    float u = (float)lam[0], v = (float)lam[1], w = (float)lam[2];
    float pu[MAX_DEGREE + 1], pv[MAX_DEGREE + 1], pw[MAX_DEGREE + 1];
    pu[0] = pv[0] = pw[0] = 1.0f;
    for (int i = 1; i <= net.n; i++) {
        pu[i] = pu[i - 1] * u;
        pv[i] = pv[i - 1] * v;
        pw[i] = pw[i - 1] * w;
    }
    for (int e = 0; e < net.d; e++) {
        float s = 0.0f;
        for (int r = 0; r < net.count; r++) {
            float t = coef[r][e] * pu[net.idx[r][0]];
            t = t * pv[net.idx[r][1]];
            t = t * pw[net.idx[r][2]];
            s = s + t;
        }
        out[e] = (double)s;
    }
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: bernstein_f32 PATCH.net");
    read_net(argv[1], &net);
    double fact[MAX_DEGREE + 1] = {1};
    for (int i = 1; i <= MAX_DEGREE; i++) fact[i] = fact[i - 1] * i;
    for (int r = 0; r < net.count; r++) {
        float m = (float)(fact[net.n] / (fact[net.idx[r][0]] * fact[net.idx[r][1]] * fact[net.idx[r][2]]));
        for (int e = 0; e < net.d; e++) coef[r][e] = m * (float)net.c[r][e];
    }
    serve(3, net.d, eval);
    return 0;
}
