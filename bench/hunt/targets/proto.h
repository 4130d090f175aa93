/* The pipe protocol of `tribez hunt`, for the benchmark's targets (bench/hunt/README.md).
 *
 * Each row arrives on standard input as one line of comma-separated hex floats (the barycentric
 * coordinates u, v, w); the target answers one line per row, in order, the value's coordinates
 * comma-separated as hex floats (printf's %a: exact). Input is read in blocks with read(2), and
 * every answer to the complete lines of a block is written before the next read, so the target
 * never sits on answers while it waits for more rows. */
#ifndef HUNT_PROTO_H
#define HUNT_PROTO_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_DEGREE 20
#define MAX_DIM 4
#define MAX_POINTS ((MAX_DEGREE + 1) * (MAX_DEGREE + 2) / 2)

/* A Bézier triangle read from a .net file (bench/hunt/make_patches.py). */
struct net {
    int n, d, count;
    int idx[MAX_POINTS][3];
    double c[MAX_POINTS][MAX_DIM];
};

static void die(const char *what) {
    fprintf(stderr, "target: %s\n", what);
    exit(2);
}

static void read_net(const char *path, struct net *net) {
    FILE *f = fopen(path, "r");
    if (!f) die("cannot open the .net file");
    if (fscanf(f, "%d %d", &net->n, &net->d) != 2 || net->n < 1 || net->n > MAX_DEGREE ||
        net->d < 1 || net->d > MAX_DIM)
        die("bad .net header");
    net->count = (net->n + 1) * (net->n + 2) / 2;
    for (int r = 0; r < net->count; r++) {
        if (fscanf(f, "%d %d %d", &net->idx[r][0], &net->idx[r][1], &net->idx[r][2]) != 3)
            die("bad .net line");
        for (int e = 0; e < net->d; e++)
            if (fscanf(f, "%lf", &net->c[r][e]) != 1) die("bad .net value");
    }
    fclose(f);
}

/* The index of multi-index (i, j, k) in the canonical order (k ascending, then j). */
static inline int rank_of(int n, int j, int k) {
    /* rows k' < k hold n + 1 - k' indices each */
    return k * (n + 1) - k * (k - 1) / 2 + j;
}

typedef void (*eval_fn)(const double *lam, double *out);

static char *out_buf;
static size_t out_len, out_cap;

static void out_flush(void) {
    size_t done = 0;
    while (done < out_len) {
        ssize_t w = write(1, out_buf + done, out_len - done);
        if (w < 0) {
            if (errno == EINTR) continue;
            exit(1);
        }
        done += (size_t)w;
    }
    out_len = 0;
}

static void out_reserve(size_t more) {
    if (out_len + more > out_cap) {
        out_cap = 2 * (out_len + more);
        out_buf = realloc(out_buf, out_cap);
        if (!out_buf) die("out of memory");
    }
}

/* Answer every row: `width` numbers in, `dim` out (written as %a of the double). */
static void serve(int width, int dim, eval_fn f) {
    size_t cap = 1 << 20, len = 0;
    char *buf = malloc(cap + 1);
    if (!buf) die("out of memory");
    for (;;) {
        ssize_t got = read(0, buf + len, cap - len);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        len += (size_t)got;
        buf[len] = 0;
        char *start = buf, *nl;
        while ((nl = memchr(start, '\n', len - (size_t)(start - buf)))) {
            *nl = 0;
            double lam[8], val[MAX_DIM];
            char *p = start;
            for (int i = 0; i < width; i++) {
                char *end;
                lam[i] = strtod(p, &end);
                if (end == p) die("a row that is not numbers");
                p = end;
                if (*p == ',') p++;
            }
            f(lam, val);
            out_reserve((size_t)dim * 32 + 2);
            for (int e = 0; e < dim; e++)
                out_len += (size_t)sprintf(out_buf + out_len, e ? ",%a" : "%a", val[e]);
            out_buf[out_len++] = '\n';
            start = nl + 1;
        }
        len -= (size_t)(start - buf);
        memmove(buf, start, len);
        if (len == cap) die("an input line over 1 MiB");
        out_flush();
    }
    out_flush();
}

#endif
