/* de Casteljau in f64 on a .net patch: level by level,
 *   b^{l-1}_{ijk} = u * b^l_{i+1,j,k} + v * b^l_{i,j+1,k} + w * b^l_{i,j,k+1},
 * each sum added left to right. */
#ifndef HUNT_CASTELJAU_H
#define HUNT_CASTELJAU_H
#include "proto.h"

static void casteljau(const struct net *net, const double *lam, double *out) {
    double b[MAX_POINTS][MAX_DIM];
    memcpy(b, net->c, sizeof b);
    double u = lam[0], v = lam[1], w = lam[2];
    for (int l = net->n; l >= 1; l--) {
        /* in place: the index (i,j,k) of degree l-1 only reads indices of degree l of rank at
         * least its own, so ascending rank order is safe */
        for (int k = 0; k <= l - 1; k++)
            for (int j = 0; j <= l - 1 - k; j++) {
                int to = rank_of(l - 1, j, k);
                int ri = rank_of(l, j, k), rj = rank_of(l, j + 1, k), rk = rank_of(l, j, k + 1);
                for (int e = 0; e < net->d; e++)
                    b[to][e] = u * b[ri][e] + v * b[rj][e] + w * b[rk][e];
            }
    }
    for (int e = 0; e < net->d; e++) out[e] = b[0][e];
}
#endif
