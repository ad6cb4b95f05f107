/* compatmesh batch: one triangulate job per line of a list, run on several
 * processes, each job writing into its own folder of the output directory
 * exactly as `compatmesh triangulate` would, then batch.json for them all. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, mkstemp, fchmod */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "batch_list.h"
#include "cli_common.h"
#include "commands.h"
#include "interrupt.h"
#include "options.h"
#include "outdir.h"
#include "progress_line.h"
#include "triangulate_job.h"
#include "worker_pool.h"
#include "write_report.h"

enum { MAX_WORKERS = 4096 };

static const option_spec batch_options[] = {
    {"out-dir", 'o', "DIR",
     "where the job folders and batch.json go (required);\n"
     "DIR is created if missing (its parent must exist)"},
    {"jobs", 'j', "N",
     "jobs run at once, each in its own process (default:\n"
     "the number of online CPUs)"},
    TRIANGULATE_FORMAT_SPEC,
    TRIANGULATE_PREVIEW_SPEC,
    TRIANGULATION_METHOD_SPECS,
    {"quiet", OPTION_QUIET, NULL,
     "only failed jobs' lines on stderr, nothing on stdout"},
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t batch_option_count = sizeof batch_options / sizeof batch_options[0];

typedef struct batch_args {
    triangulate_job job; /* the options every job shares */
    const char *list;
    const char *out_dir;
    long workers;
    int help;
} batch_args;

static int handle_batch_option(void *context, int key, const char *value, cli_error *error)
{
    batch_args *args = context;
    if (key == 0) {
        if (args->list) {
            cli_error_set(error, "batch: takes one LIST, got '%s' and '%s' (the inputs of a "
                          "job go on its line of LIST)", args->list, value);
            return CLI_EXIT_USAGE;
        }
        args->list = value;
        return CLI_EXIT_OK;
    }
    int code = triangulate_job_option(&args->job, "batch", key, value, error);
    if (code >= 0) return code;
    switch (key) {
    case 'o':
        args->out_dir = value;
        return CLI_EXIT_OK;
    case 'j':
        args->workers = parse_whole_number(value, 1, MAX_WORKERS);
        if (args->workers > 0) return CLI_EXIT_OK;
        cli_error_set(error, "batch: --jobs needs a whole number in [1, %d], got '%s'",
                      MAX_WORKERS, value);
        return CLI_EXIT_USAGE;
    case 'h':
        args->help = 1;
        return CLI_EXIT_OK;
    default:
        cli_error_set(error, "batch: unhandled option %d", key);
        return CLI_EXIT_INTERNAL;
    }
}

static void print_batch_help(FILE *out)
{
    fputs("Usage: compatmesh batch LIST --out-dir DIR [--jobs N] [OPTIONS]\n"
          "\n"
          "Runs one 'compatmesh triangulate' job per line of LIST, N at a time,\n"
          "each in its own process and its own folder of DIR. The options apply to\n"
          "every job; see 'compatmesh triangulate --help' for the inputs and what\n"
          "a job writes.\n"
          "\n"
          "LIST, one job per line:\n"
          "  [NAME:] IN1 IN2 [IN3 ...]\n"
          "  the job's input files separated by blanks (a path cannot hold a blank\n"
          "  or '#'); relative paths are relative to LIST's folder; '#' starts a\n"
          "  comment; blank lines are ignored. A first field ending in ':' names\n"
          "  the job's folder (not starting with '.', no '/', not batch.json);\n"
          "  without it the folder is LINE-STEM, the line number and the first\n"
          "  input's file name without extension (\"7-a\" for line 7, a.xy ...).\n"
          "  Every line is checked before any job starts: a missing file, fewer\n"
          "  than two inputs or a folder name used twice is an error naming\n"
          "  LIST:LINE, and nothing is written.\n"
          "\n"
          "Options:\n", out);
    print_options(out, batch_options, batch_option_count);
    fputs("\n"
          "Outputs:\n"
          "  DIR/FOLDER/      each job's meshes, report.json and previews, moved in\n"
          "                   whole when the job succeeded (as triangulate does);\n"
          "                   a failed job leaves its folder as it was\n"
          "  DIR/batch.json   list, out_dir, workers, jobs_total, ok, bad_input,\n"
          "                   internal_failure, exit_code, cpu_seconds, wall_seconds\n"
          "                   and per job (in LIST order) line, name, out_dir,\n"
          "                   inputs, status (ok, bad_input, internal_failure),\n"
          "                   exit_code, message (null on success), steiner and\n"
          "                   min_angle_deg per input (null on failure),\n"
          "                   cpu_seconds (user + system time of its process);\n"
          "                   an old batch.json is removed when the jobs start\n"
          "  stderr           one line per finished job (--quiet: failed ones only)\n"
          "\n"
          "A failing job does not stop the others. Exit status: 0 if every job\n"
          "succeeded, 2 if a job had bad input and none failed internally, 1 if\n"
          "any failed internally; 2 also for a bad command line or LIST; 130 when\n"
          "interrupted (running jobs are stopped and leave nothing; finished jobs'\n"
          "folders are complete; batch.json is not written).\n", out);
}

static int parse_batch_args(int argc, char **argv, batch_args *args, cli_error *error)
{
    memset(args, 0, sizeof *args);
    int code = triangulate_job_init(&args->job, argc, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_options(argc, argv, "batch", batch_options, batch_option_count,
                         handle_batch_option, args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    if (!args->list || !args->out_dir) {
        cli_error_set(error, "batch: %s is required (see 'compatmesh batch --help')",
                      !args->list ? "LIST" : "--out-dir DIR");
        return CLI_EXIT_USAGE;
    }
    if (args->workers == 0) {
        long online = sysconf(_SC_NPROCESSORS_ONLN);
        args->workers = online < 1 ? 1 : online > MAX_WORKERS ? MAX_WORKERS : online;
    }
    return CLI_EXIT_OK;
}

/* The whole batch: its list, each job's folder and how each job ended. */
typedef struct batch_run {
    const batch_args *args;
    batch_list list;
    char *out_dir;            /* DIR without trailing slashes */
    char **job_dirs;          /* DIR/NAME per job */
    batch_job_report *jobs;   /* per job, filled as it ends */
    char **messages;          /* per job: the one-line error, "" on success */
    double *angles;           /* input_count per job, in list order */
    size_t finished;
} batch_run;

static void batch_run_free(batch_run *b)
{
    for (size_t i = 0; i < b->list.count; i++) {
        if (b->job_dirs) free(b->job_dirs[i]);
        if (b->messages) free(b->messages[i]);
    }
    free(b->job_dirs);
    free(b->messages);
    free(b->jobs);
    free(b->angles);
    free(b->out_dir);
    batch_list_free(&b->list);
}

/* The job's options as the command line gave them, its inputs from LIST. */
static triangulate_job job_of(const batch_run *b, size_t index)
{
    triangulate_job job = b->args->job;
    job.tri.inputs = (const char **)b->list.entries[index].inputs;
    job.tri.input_count = b->list.entries[index].input_count;
    job.out_dir = b->job_dirs[index];
    return job;
}

/* Before anything runs: the options must fit every line (--pin names one
 * vertex per input), and each job gets its folder and its report entry. */
static int prepare(batch_run *b, cli_error *error)
{
    size_t count = b->list.count, angles = 0;
    for (size_t i = 0; i < count; i++) angles += b->list.entries[i].input_count;
    b->job_dirs = calloc(count, sizeof *b->job_dirs);
    b->messages = calloc(count, sizeof *b->messages);
    b->jobs = calloc(count, sizeof *b->jobs);
    b->angles = calloc(angles, sizeof *b->angles);
    if (!b->job_dirs || !b->messages || !b->jobs || !b->angles) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    angles = 0;
    for (size_t i = 0; i < count; i++) {
        const batch_entry *e = &b->list.entries[i];
        b->job_dirs[i] = path_join(b->out_dir, e->name);
        if (!b->job_dirs[i]) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        char where[64 + 1024];
        snprintf(where, sizeof where, "%s:%ld", b->args->list, e->line);
        triangulate_job job = job_of(b, i);
        int code = triangulation_args_check(&job.tri, where, error);
        if (code != CLI_EXIT_OK) return code;
        b->jobs[i] = (batch_job_report){e->line, e->name, b->job_dirs[i],
                                        (const char *const *)e->inputs, e->input_count,
                                        CLI_EXIT_INTERNAL, "", 0, b->angles + angles, 0};
        angles += e->input_count;
    }
    cli_progress_set_mode(PROGRESS_QUIET); /* jobs show no stages */
    return CLI_EXIT_OK;
}

/* In the job's process: the triangulate run, then its record on the
 * channel: "CODE STEINER ANGLE..." and, on the next line, the message. */
static int run_job(void *context, size_t index, int channel)
{
    const batch_run *b = context;
    triangulate_job job = job_of(b, index);
    /* This process's own copy of the job's angles. */
    triangulate_outcome outcome = {0, b->angles + (b->jobs[index].min_angle_deg - b->angles)};
    cli_error error = {{0}};
    int code = triangulate_job_run(&job, &outcome, &error);
    FILE *out = fdopen(channel, "w");
    if (!out) return CLI_EXIT_INTERNAL;
    fprintf(out, "%d %zu", code, outcome.steiner);
    for (size_t g = 0; g < job.tri.input_count; g++)
        fprintf(out, " %.17g", code == CLI_EXIT_OK ? outcome.min_angle_deg[g] : 0.0);
    fprintf(out, "\n%s", error.message);
    return fclose(out) == 0 ? code : CLI_EXIT_INTERNAL;
}

/* The record of run_job into the job's entry; 0 if it is not one. */
static int read_record(batch_run *b, size_t index, const char *record, int exit_code)
{
    batch_job_report *job = &b->jobs[index];
    char *end;
    long code = strtol(record, &end, 10);
    if (end == record || code != exit_code) return 0;
    job->steiner = (size_t)strtoull(end, &end, 10);
    double *angles = b->angles + (job->min_angle_deg - b->angles);
    for (size_t g = 0; g < job->input_count; g++) angles[g] = strtod(end, &end);
    if (*end != '\n') return 0;
    b->messages[index] = strdup(end + 1);
    return 1;
}

static void print_job_line(const batch_run *b, size_t index)
{
    const batch_job_report *job = &b->jobs[index];
    if (job->exit_code != CLI_EXIT_OK) {
        fprintf(stderr, "compatmesh: batch: [%zu/%zu] %s %s: %s\n", b->finished, b->list.count,
                job->name, job->exit_code == CLI_EXIT_USAGE ? "bad input" : "internal failure",
                job->message);
        return;
    }
    if (b->args->job.tri.quiet) return;
    fprintf(stderr, "compatmesh: batch: [%zu/%zu] %s ok: %zu Steiner, smallest angles", b->finished,
            b->list.count, job->name, job->steiner);
    for (size_t g = 0; g < job->input_count; g++)
        fprintf(stderr, "%s %.1f", g ? "," : "", job->min_angle_deg[g]);
    fprintf(stderr, " deg, %.2f s CPU\n", job->cpu_seconds);
}

/* In the parent, as a job's process ends. */
static void job_done(void *context, size_t index, const worker_result *result)
{
    batch_run *b = context;
    batch_job_report *job = &b->jobs[index];
    job->cpu_seconds = result->cpu_seconds;
    job->exit_code = result->exit_code;
    if (result->failure) {
        job->exit_code = CLI_EXIT_INTERNAL;
        b->messages[index] = strdup(result->failure);
    } else if (result->exit_code == CLI_EXIT_INTERRUPTED && result->record_length == 0) {
        /* Stopped before it started, or by its watchdog: it wrote nothing. */
        b->messages[index] = strdup("interrupted; nothing written");
    } else if (!read_record(b, index, result->record, result->exit_code)) {
        char message[96];
        snprintf(message, sizeof message, "the job's process ended (exit status %d) without "
                 "saying how the job went", result->exit_code);
        job->exit_code = CLI_EXIT_INTERNAL;
        b->messages[index] = strdup(message);
    }
    job->message = b->messages[index] ? b->messages[index] : "out of memory";
    b->finished++;
    if (!(interrupted && job->exit_code == CLI_EXIT_INTERRUPTED)) print_job_line(b, index);
}

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* DIR itself, if missing, and no batch.json of an earlier batch: the one
 * there always describes the folders beside it. */
static int open_out_dir(const batch_run *b, const char *report, cli_error *error)
{
    int code = staged_output_check(b->out_dir, error);
    if (code != CLI_EXIT_OK) return code;
    /* An output never replaces an input, nor the list. */
    const char *list[1] = {b->args->list};
    code = refuse_input_as_output(report, list, 1, error);
    for (size_t i = 0; i < b->list.count && code == CLI_EXIT_OK; i++)
        code = refuse_input_as_output(report, (const char *const *)b->list.entries[i].inputs,
                                      b->list.entries[i].input_count, error);
    if (code != CLI_EXIT_OK) return code;
    if (mkdir(b->out_dir, 0777) != 0 && errno != EEXIST) {
        cli_error_set(error, "cannot create %s: %s", b->out_dir, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    if (unlink(report) != 0 && errno != ENOENT) {
        cli_error_set(error, "cannot replace %s: %s", report, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

/* batch.json appears whole: written beside, then renamed. */
static int write_batch_json(const batch_run *b, const char *report, int exit_code,
                            double wall_seconds, cli_error *error)
{
    char *temporary = path_join(b->out_dir, ".batch.json.XXXXXX");
    if (!temporary) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    int fd = mkstemp(temporary);
    if (fd < 0) {
        cli_error_set(error, "cannot create a file in %s: %s", b->out_dir, strerror(errno));
        free(temporary);
        return CLI_EXIT_INTERNAL;
    }
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask); /* as fopen would have made it */
    close(fd);
    batch_report_info info = {b->args->list, b->out_dir, b->args->workers, exit_code,
                              wall_seconds, b->jobs, b->list.count};
    int code = write_batch_report(temporary, &info, error);
    if (code == CLI_EXIT_OK && rename(temporary, report) != 0) {
        cli_error_set(error, "cannot create %s: %s", report, strerror(errno));
        code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) unlink(temporary);
    free(temporary);
    return code;
}

/* 1 if any job failed internally, else 2 if any had bad input, else 0. */
static int batch_exit_code(const batch_run *b, size_t counts[3])
{
    counts[0] = counts[1] = counts[2] = 0;
    for (size_t i = 0; i < b->list.count; i++) {
        int code = b->jobs[i].exit_code;
        counts[code == CLI_EXIT_OK ? 0 : code == CLI_EXIT_USAGE ? 1 : 2]++;
    }
    return counts[2] ? CLI_EXIT_INTERNAL : counts[1] ? CLI_EXIT_USAGE : CLI_EXIT_OK;
}

static int batch(const batch_args *args, cli_error *error)
{
    batch_run b = {0};
    b.args = args;
    double start = seconds_now();
    int code = batch_list_read(args->list, &b.list, error);
    size_t length = strlen(args->out_dir);
    while (length > 1 && args->out_dir[length - 1] == '/') length--;
    if (code == CLI_EXIT_OK && !(b.out_dir = strndup(args->out_dir, length))) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) code = prepare(&b, error);
    char *report = code == CLI_EXIT_OK ? path_join(b.out_dir, "batch.json") : NULL;
    if (code == CLI_EXIT_OK && !report) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK && interrupted) {
        cli_error_set(error, "interrupted; nothing written");
        code = CLI_EXIT_INTERRUPTED;
    }
    if (code == CLI_EXIT_OK) code = open_out_dir(&b, report, error);
    /* From here the batch only waits for its jobs' processes. */
    if (code == CLI_EXIT_OK) catch_interrupts_without_watchdog();
    if (code == CLI_EXIT_OK &&
        run_workers(b.list.count, args->workers, run_job, job_done, &b) != CLI_EXIT_OK) {
        size_t done = 0;
        for (size_t i = 0; i < b.list.count; i++) done += b.jobs[i].exit_code == CLI_EXIT_OK;
        cli_error_set(error, "batch: interrupted; %zu of %zu jobs had succeeded (their "
                      "folders are complete), the others left nothing; batch.json not written",
                      done, b.list.count);
        code = CLI_EXIT_INTERRUPTED;
    }
    size_t counts[3] = {0, 0, 0};
    int outcome = code == CLI_EXIT_OK ? batch_exit_code(&b, counts) : code;
    if (code == CLI_EXIT_OK)
        code = write_batch_json(&b, report, outcome, seconds_now() - start, error);
    if (code == CLI_EXIT_OK && !args->job.tri.quiet)
        printf("wrote %s: %zu jobs, %zu ok, %zu bad input, %zu internal failure%s\n", report,
               b.list.count, counts[0], counts[1], counts[2], counts[2] == 1 ? "" : "s");
    free(report);
    batch_run_free(&b);
    return code == CLI_EXIT_OK ? outcome : code;
}

int run_batch(int argc, char **argv)
{
    batch_args args;
    cli_error error = {{0}};
    int code = parse_batch_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_batch_help(stdout);
    else if (code == CLI_EXIT_OK) code = batch(&args, &error);
    if (code != CLI_EXIT_OK && error.message[0]) cli_print_error(&error);
    triangulation_args_free(&args.job.tri);
    return code;
}
