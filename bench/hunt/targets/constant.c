/* A target that answers the same constant, VALUE in each of DIM coordinates, to every row without
 * reading it (for the hunt's own cost and the pipe's throughput). With RECORD, it also copies
 * every row it is given to that file. Usage: constant VALUE DIM [RECORD] */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void put(int fd, const char *p, size_t n) {
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            exit(1);
        }
        p += w;
        n -= (size_t)w;
    }
}

int main(int argc, char **argv) {
    if (argc < 3 || argc > 4 || strlen(argv[1]) > 40) {
        fprintf(stderr, "usage: constant VALUE DIM [RECORD]\n");
        return 2;
    }
    const char *value = argv[1];
    int dim = atoi(argv[2]);
    if (dim < 1 || dim > 16) {
        fprintf(stderr, "constant: DIM must be 1 to 16\n");
        return 2;
    }
    FILE *rec = argc == 4 ? fopen(argv[3], "w") : NULL;
    if (argc == 4 && !rec) {
        fprintf(stderr, "constant: cannot write %s\n", argv[3]);
        return 2;
    }
    char line[16 * 42 + 1];
    size_t ll = 0;
    for (int e = 0; e < dim; e++) {
        if (e) line[ll++] = ',';
        memcpy(line + ll, value, strlen(value));
        ll += strlen(value);
    }
    line[ll++] = '\n';
    static char in[1 << 20];
    char *out = malloc(sizeof in * ll);
    for (;;) {
        ssize_t got = read(0, in, sizeof in);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        if (rec) fwrite(in, 1, (size_t)got, rec);
        size_t o = 0;
        for (char *p = in; (p = memchr(p, '\n', (size_t)(in + got - p))); p++) {
            memcpy(out + o, line, ll);
            o += ll;
        }
        put(1, out, o);
    }
    if (rec) fclose(rec);
    return 0;
}
