/*
 * eval_shim.c — a generated header compiled with tfit_shim.c and libtfit
 * into a shared object and loaded (eval_shim.h).
 */
#include <ctype.h>
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/interrupts.h"
#include "base/log.h"
#include "cli/eval_shim.h"

#define MAX_ARGS 64

/* "PREFIX { ws } IDENT { ws } END": IDENT (without tfit_) into name. */
static int declares(const char *line, const char *prefix, const char *end, char *name)
{
    size_t n = strlen(prefix);
    if (strncmp(line, prefix, n) != 0 || strncmp(line + n, "tfit_", 5) != 0) {
        return 0;
    }
    const char *id = line + n + 5;
    size_t len = 0;
    while (isalnum((unsigned char)id[len]) || id[len] == '_') {
        ++len;
    }
    if (len == 0 || len >= TF_EVAL_NAME_MAX || strncmp(id + len, end, strlen(end)) != 0) {
        return 0;
    }
    memcpy(name, id, len);
    name[len] = '\0';
    return 1;
}

/* Adds the declarations of one file's lines to d. */
static int scan(tf_ctx *ctx, const char *path, tf_eval_decls *d)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return tf_fail(ctx, "%s: %s", path, strerror(errno));
    }
    char line[1024];
    while (fgets(line, sizeof line, f) != NULL) {
        struct {
            const char *prefix, *end;
            size_t *n;
            char (*names)[TF_EVAL_NAME_MAX];
        } kinds[4] = {
            {"extern const tfit_model ", ";", &d->n_models, d->models},
            {"extern const tfit_model_q31 ", ";", &d->n_models_q31, d->models_q31},
            {"static const tfit_golden ", " =", &d->n_goldens, d->goldens},
            {"static const tfit_golden_q31 ", " =", &d->n_goldens_q31, d->goldens_q31},
        };
        for (int k = 0; k < 4; ++k) {
            char name[TF_EVAL_NAME_MAX];
            if (declares(line, kinds[k].prefix, kinds[k].end, name)) {
                if (*kinds[k].n == TF_EVAL_MAX_MODELS) {
                    fclose(f);
                    return tf_fail(ctx, "%s: more than %d models", path, TF_EVAL_MAX_MODELS);
                }
                memcpy(kinds[k].names[(*kinds[k].n)++], name, TF_EVAL_NAME_MAX);
            }
        }
    }
    int bad = ferror(f);
    fclose(f);
    return bad ? tf_fail(ctx, "%s: read error", path) : 0;
}

int tf_eval_decls_read(tf_ctx *ctx, const char *path, int golden, tf_eval_decls *d)
{
    memset(d, 0, sizeof *d);
    size_t len = strlen(path);
    if (len < 3 || strcmp(path + len - 2, ".h") != 0 || len + 16 > PATH_MAX) {
        return tf_fail(ctx, "%s: not a generated header (NAME.h)", path);
    }
    if (scan(ctx, path, d) != 0) {
        return -1;
    }
    if (d->n_models == 0) {
        return tf_fail(ctx, "%s: declares no tfit_model: not a generated header", path);
    }
    char golden_path[PATH_MAX];
    snprintf(golden_path, sizeof golden_path, "%.*s_golden.h", (int)(len - 2), path);
    d->has_golden_file = golden && access(golden_path, R_OK) == 0;
    return d->has_golden_file ? scan(ctx, golden_path, d) : 0;
}

/* The tool's prefix: the folder above the executable's. */
static int prefix_dir(tf_ctx *ctx, char *dir, size_t size)
{
    ssize_t n = readlink("/proc/self/exe", dir, size - 1);
    if (n <= 0) {
        return tf_fail(ctx, "cannot find the tool's own path (/proc/self/exe): %s",
                       strerror(errno));
    }
    dir[n] = '\0';
    for (int up = 0; up < 2; ++up) {
        char *slash = strrchr(dir, '/');
        if (slash == NULL) {
            return tf_fail(ctx, "cannot find the tool's prefix from %s", dir);
        }
        *slash = '\0';
    }
    return 0;
}

/* The list of X-macro lines tfit_shim.c includes (TF_SHIM_LIST_FILE). */
static int write_list(tf_ctx *ctx, const char *file, const tf_eval_decls *d)
{
    FILE *f = fopen(file, "w");
    if (f == NULL) {
        return tf_fail(ctx, "%s: %s", file, strerror(errno));
    }
    for (size_t i = 0; i < d->n_models; ++i) {
        fprintf(f, "TF_SHIM_MODEL(tfit_%s)\n", d->models[i]);
    }
    for (size_t i = 0; i < d->n_models_q31; ++i) {
        fprintf(f, "TF_SHIM_MODEL_Q31(tfit_%s)\n", d->models_q31[i]);
    }
    for (size_t i = 0; i < d->n_goldens; ++i) {
        fprintf(f, "TF_SHIM_GOLDEN(tfit_%s)\n", d->goldens[i]);
    }
    for (size_t i = 0; i < d->n_goldens_q31; ++i) {
        fprintf(f, "TF_SHIM_GOLDEN_Q31(tfit_%s)\n", d->goldens_q31[i]);
    }
    return fclose(f) != 0 ? tf_fail(ctx, "%s: %s", file, strerror(errno)) : 0;
}

/* Runs argv with its output into log; 0 when it exits 0. */
static int run(tf_ctx *ctx, char *const *argv, const char *log)
{
    pid_t pid = fork();
    if (pid < 0) {
        return tf_fail(ctx, "cannot start %s: %s", argv[0], strerror(errno));
    }
    if (pid == 0) {
        tf_interrupts_child(); /* the compiler ends by the terminal's signals as the tool does */
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execvp(argv[0], argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            return tf_fail(ctx, "waiting for %s: %s", argv[0], strerror(errno));
        }
    }
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : -1;
}

/* The compiler's message: its log file, up to ctx's buffer. */
static int compile_failed(tf_ctx *ctx, const char *path, const char *cc, const char *log)
{
    char text[2048] = "";
    FILE *f = fopen(log, "r");
    if (f != NULL) {
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = '\0';
        fclose(f);
    }
    return tf_fail(ctx, "%s: does not compile with libtfit (CC=%s):\n%s", path, cc, text);
}

/* Builds dir/NAME.so from the header at path. */
static int build(tf_ctx *ctx, const char *path, const tf_eval_decls *d, const char *dir)
{
    char prefix[PATH_MAX], shim[PATH_MAX + 32], inc[PATH_MAX + 32], lib[PATH_MAX + 64];
    if (prefix_dir(ctx, prefix, sizeof prefix) != 0) {
        return -1;
    }
    snprintf(shim, sizeof shim, "%s/share/tfit/tfit_shim.c", prefix);
    snprintf(inc, sizeof inc, "-I%s/include", prefix);
    snprintf(lib, sizeof lib, "%s/lib/tfit/native-pic/libtfit.a", prefix);
    if (access(shim, R_OK) != 0 || access(lib, R_OK) != 0 || access(inc + 2, R_OK) != 0) {
        return tf_fail(ctx, "the header evaluator is not installed beside the tool: %s or %s "
                            "is missing (make install, or make in the source tree)",
                       shim, lib);
    }
    char list[PATH_MAX], so[PATH_MAX], log[PATH_MAX], hdir[PATH_MAX], base[PATH_MAX];
    snprintf(list, sizeof list, "%s/shim_list.h", dir);
    snprintf(log, sizeof log, "%s/cc.log", dir);
    snprintf(so, sizeof so, "%s/header.so", dir);
    if (write_list(ctx, list, d) != 0) {
        return -1;
    }
    const char *slash = strrchr(path, '/');
    snprintf(hdir, sizeof hdir, "-I%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
    snprintf(base, sizeof base, "%s", slash ? slash + 1 : path);
    base[strlen(base) - 2] = '\0';

    char upper[PATH_MAX], def_impl[PATH_MAX + 32], def_hdr[PATH_MAX + 32],
        def_golden[PATH_MAX + 48], def_list[PATH_MAX + 32];
    for (size_t i = 0; i <= strlen(base); ++i) {
        upper[i] = (char)toupper((unsigned char)base[i]);
    }
    snprintf(def_impl, sizeof def_impl, "-DTFIT_%s_IMPLEMENTATION", upper);
    snprintf(def_hdr, sizeof def_hdr, "-DTF_SHIM_HEADER_FILE=\"%s.h\"", base);
    snprintf(def_golden, sizeof def_golden, "-DTF_SHIM_GOLDEN_FILE=\"%s_golden.h\"", base);
    snprintf(def_list, sizeof def_list, "-I%s", dir);

    /* $CC split at blanks, then the bit-exact flags of the project's builds. */
    const char *env = getenv("CC");
    char cc[1024];
    snprintf(cc, sizeof cc, "%s", env != NULL && env[strspn(env, " \t")] != '\0' ? env : "cc");
    char *argv[MAX_ARGS];
    int n = 0;
    for (char *save = NULL, *t = strtok_r(cc, " \t", &save); t != NULL && n < MAX_ARGS - 20;
         t = strtok_r(NULL, " \t", &save)) {
        argv[n++] = t;
    }
    char *flags[] = {"-std=c11", "-O2", "-ffp-contract=off", "-fPIC", "-shared", hdir, inc,
                     def_list, def_hdr, "-DTF_SHIM_LIST_FILE=\"shim_list.h\"", def_impl};
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; ++i) {
        argv[n++] = flags[i];
    }
    if (d->has_golden_file) {
        argv[n++] = def_golden;
    }
    argv[n++] = shim;
    argv[n++] = lib;
    argv[n++] = "-o";
    argv[n++] = so;
    argv[n] = NULL;
    return run(ctx, argv, log) != 0 ? compile_failed(ctx, path, env ? env : "cc", log) : 0;
}

/* dlsym into a function pointer (POSIX guarantees the representation). */
static int entry(tf_ctx *ctx, void *so, const char *name, void *fn, size_t size)
{
    void *p = dlsym(so, name);
    if (p == NULL) {
        return tf_fail(ctx, "the header evaluator lacks %s (an older tfit_shim.c?)", name);
    }
    memcpy(fn, &p, size);
    return 0;
}

#define ENTRY(field, name) entry(ctx, sh->so, name, &sh->field, sizeof sh->field)

static int load(tf_ctx *ctx, tf_eval_shim *sh)
{
    char so[sizeof sh->dir + 16];
    snprintf(so, sizeof so, "%s/header.so", sh->dir);
    sh->so = dlopen(so, RTLD_NOW | RTLD_LOCAL);
    if (sh->so == NULL) {
        return tf_fail(ctx, "cannot load the compiled header: %s", dlerror());
    }
    return ENTRY(model_info, "tf_shim_model_info") || ENTRY(eval, "tf_shim_eval") ||
                   ENTRY(eval_region, "tf_shim_eval_region") ||
                   ENTRY(cut_golden_s, "tf_shim_cut_golden_s") ||
                   ENTRY(goldens, "tf_shim_goldens") || ENTRY(golden, "tf_shim_golden") ||
                   ENTRY(model_q31_info, "tf_shim_model_q31_info") ||
                   ENTRY(eval_q31, "tf_shim_eval_q31") ||
                   ENTRY(goldens_q31, "tf_shim_goldens_q31") ||
                   ENTRY(golden_q31, "tf_shim_golden_q31")
               ? -1
               : 0;
}

int tf_eval_shim_open(tf_ctx *ctx, tf_eval_shim *sh, const char *path, const tf_eval_decls *d)
{
    memset(sh, 0, sizeof *sh);
    const char *tmp = getenv("TMPDIR");
    snprintf(sh->dir, sizeof sh->dir, "%s/tissuefit-eval-XXXXXX",
             tmp != NULL && tmp[0] == '/' ? tmp : "/tmp");
    if (mkdtemp(sh->dir) == NULL) {
        int e = errno;
        sh->dir[0] = '\0';
        return tf_fail(ctx, "cannot make a temporary folder: %s", strerror(e));
    }
    if (build(ctx, path, d, sh->dir) != 0 || load(ctx, sh) != 0) {
        tf_eval_shim_close(sh);
        return -1;
    }
    return 0;
}

void tf_eval_shim_close(tf_eval_shim *sh)
{
    if (sh->so != NULL) {
        dlclose(sh->so);
        sh->so = NULL;
    }
    if (sh->dir[0] != '\0') {
        static const char *const files[] = {"shim_list.h", "cc.log", "header.so"};
        char f[sizeof sh->dir + 16];
        for (size_t i = 0; i < sizeof files / sizeof files[0]; ++i) {
            snprintf(f, sizeof f, "%s/%s", sh->dir, files[i]);
            unlink(f);
        }
        rmdir(sh->dir);
        sh->dir[0] = '\0';
    }
}
