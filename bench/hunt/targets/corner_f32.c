/* Target (4): de Casteljau in f64, correct except that when a barycentric coordinate is above
 * 0.999 it first rounds all its inputs to f32. Usage: corner_f32 PATCH.net */
#include "casteljau.h"

static struct net net;

static void eval(const double *lam, double *out) {
    double l[3] = {lam[0], lam[1], lam[2]};
    if (l[0] > 0.999 || l[1] > 0.999 || l[2] > 0.999)
        for (int i = 0; i < 3; i++) l[i] = (double)(float)l[i];
    casteljau(&net, l, out);
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: corner_f32 PATCH.net");
    read_net(argv[1], &net);
    serve(3, net.d, eval);
    return 0;
}
