/* A correct target: de Casteljau in f64 (casteljau.h), within `cond` everywhere (the hunt's own
 * cost on rows that pass). Usage: casteljau PATCH.net */
#include "casteljau.h"

static struct net net;

static void eval(const double *lam, double *out) { casteljau(&net, lam, out); }

int main(int argc, char **argv) {
    if (argc != 2) die("usage: casteljau PATCH.net");
    read_net(argv[1], &net);
    serve(3, net.d, eval);
    return 0;
}
