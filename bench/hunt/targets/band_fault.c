/* Target (3): de Casteljau in f64, correct except for one planted fault: when the smallest
 * barycentric coordinate lies in [1e-9, 2e-9], the result is multiplied by 1 + 2^-20.
 * Usage: band_fault PATCH.net */
#include "casteljau.h"

static struct net net;

static void eval(const double *lam, double *out) {
    casteljau(&net, lam, out);
    double m = lam[0] < lam[1] ? lam[0] : lam[1];
    if (lam[2] < m) m = lam[2];
    if (m >= 1e-9 && m <= 2e-9)
        for (int e = 0; e < net.d; e++) out[e] *= 1.0 + 0x1p-20;
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: band_fault PATCH.net");
    read_net(argv[1], &net);
    serve(3, net.d, eval);
    return 0;
}
