#!/usr/bin/env node
// Entry of the `hairsketch` command: runs web/cli/main.ts through tsx (a dev dependency).
import { register } from 'tsx/esm/api';

register();
const { main } = await import('../web/cli/main.ts');
process.exitCode = await main(process.argv.slice(2));
