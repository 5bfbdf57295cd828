// Types of scripts/benchResults.mjs (plain JavaScript, so that `node` scripts use it too).
export declare const RESULTS_DIR: string;

export interface BenchContext {
  date: string;
  commit: string | null;
  uncommittedChanges: boolean | null;
  machine: {
    cpu: string | null;
    cores: number;
    memoryMB: number;
    os: string;
    node: string;
    loadAverage: string | null;
  };
}

export declare function benchContext(): BenchContext;

export interface BenchResults {
  /** One line: what the benchmark is. */
  title: string;
  /** The script that wrote the file, e.g. scripts/bench-detail.ts. */
  script: string;
  /** How to run it again, e.g. `npm run bench:detail`. */
  command: string;
  /** What is measured, and how (units, medians, what a row is). */
  measures: string;
  /** The run's settings (grids, strand counts, environment overrides). */
  config: unknown;
  /** Every measurement of the run. */
  results: unknown;
  /** A markdown table of the results (written to bench-results/<name>.md too). */
  table?: string;
}

export declare function writeBenchResults(name: string, r: BenchResults): string[];
