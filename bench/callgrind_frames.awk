# Reads the callgrind dumps of one simulator run (callgrind --dump-every-bb writes one file per
# window of the run) and prints one line per board library:
#   <library> frames=<n> mean=<i> busiest=<i> windows=<n> blocks=<count>x<Block>,...
# mean and busiest are host instructions per frame of the board's own engine: the inclusive cost
# of Engine::run_frame minus its calls into the simulator's hal:: functions, over the whole run
# and over the busiest window holding at least min_frames frames. Blocks per frame come from the
# calls Engine::run_stage makes. Only Engine::run_frame is collected (--toggle-collect).
# Used by bench/measure_example_frames.sh; input format: the callgrind manual, "Callgrind Format".

# "(12) name" defines id 12 in this file's table of `kind`; "(12)" refers to it; a bare name is itself.
function name_of(kind, text,    id, rest) {
  if (match(text, /^\([0-9]+\)/)) {
    id = substr(text, 2, RLENGTH - 2)
    rest = substr(text, RLENGTH + 2)
    if (rest != "") names[kind, id] = rest
    return names[kind, id]
  }
  return text
}

function record_call(count, cost,    block) {
  if (callee == run_frame) {
    frames[window, callee_object] += count
    frame_cost[window, callee_object] += cost
    libraries[callee_object] = 1
  } else if (index(callee, "stepdance::hal::") == 1 && index(caller, "stepdance::hal::") != 1) {
    hal_cost[window, object] += cost
  } else if (index(caller, "stepdance::Engine::run_stage(") == 1) {
    block = callee
    sub(/::run\(\)$/, "", block)
    sub(/^stepdance::/, "", block)
    block_calls[object, block] += count
  }
}

BEGIN {
  run_frame = "stepdance::Engine::run_frame()"
  if (min_frames == "") min_frames = 1000
}
FNR == 1 { ++window; delete names; object = ""; caller = "" }
/^ob=/ { object = name_of("ob", substr($0, 4)); callee_object = object; next }
/^fn=/ { caller = name_of("fn", substr($0, 4)); callee_object = object; next }
/^cob=/ { callee_object = name_of("ob", substr($0, 5)); next }
/^cfn=/ { callee = name_of("fn", substr($0, 5)); next }
/^calls=/ { split(substr($0, 7), call, " "); pending = 1; next }
pending {
  # The line after calls= is "<position> <inclusive cost>" of those calls.
  pending = 0
  record_call(call[1], $2)
  callee_object = object  # a call without cob= stays in the caller's library
  next
}

END {
  for (library in libraries) {
    total_frames = 0; total_cost = 0; busiest = 0
    for (w = 1; w <= window; ++w) {
      f = frames[w, library]
      c = frame_cost[w, library] - hal_cost[w, library]
      total_frames += f
      total_cost += c
      if (f >= min_frames && c / f > busiest) busiest = c / f
    }
    if (total_frames == 0) continue
    # Blocks per frame, most first (then by name), as "3xChannel,2xEncoder,...".
    n = 0
    for (key in block_calls) {
      split(key, part, SUBSEP)
      if (part[1] != library) continue
      ++n
      count[n] = block_calls[key] / total_frames
      kind[n] = part[2]
      for (i = n; i > 1 && (count[i] > count[i - 1] || (count[i] == count[i - 1] && kind[i] < kind[i - 1])); --i) {
        swap = count[i]; count[i] = count[i - 1]; count[i - 1] = swap
        swap = kind[i]; kind[i] = kind[i - 1]; kind[i - 1] = swap
      }
    }
    blocks = ""
    for (i = 1; i <= n; ++i) blocks = blocks (i > 1 ? "," : "") sprintf("%.3gx%s", count[i], kind[i])
    printf "%s frames=%d mean=%.0f busiest=%.0f windows=%d blocks=%s\n", library, total_frames,
           total_cost / total_frames, busiest, window, blocks
  }
}
