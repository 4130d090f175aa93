/* Target (4): de Casteljau in f64, correct except that when a barycentric coordinate is above
 * 0.999 it first rounds all its inputs to f32. Usage: corner_f32 PATCH.net */
#include "casteljau.h"

static struct net net;

/* x rounded to binary32 (one conversion each way; no loop: GCC 12 at -O2 vectorised a loop of
 * these over the three coordinates into code that gave other numbers) */
static double to_f32(double x) {
    volatile float f = (float)x;
    return (double)f;
}

static void eval(const double *lam, double *out) {
    double l[3] = {lam[0], lam[1], lam[2]};
    if (l[0] > 0.999 || l[1] > 0.999 || l[2] > 0.999) {
        l[0] = to_f32(l[0]);
        l[1] = to_f32(l[1]);
        l[2] = to_f32(l[2]);
    }
    casteljau(&net, l, out);
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: corner_f32 PATCH.net");
    read_net(argv[1], &net);
    serve(3, net.d, eval);
    return 0;
}
