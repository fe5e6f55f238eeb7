// Lets a board's table call its own functions directly, past emscripten's JavaScript stubs.
// Linked with --post-js (wasm/CMakeLists.txt): it runs inside the module's factory, where the
// loader's own names (loadWebAssemblyModule, wasmTable, HEAP32, ...) are in scope. Written for
// Debian's emscripten 3.1.6; without them it does nothing (the boards then run as before).
//
// This emscripten's linker (wasm-ld, LLVM 14) makes a side module import the weak functions it
// defines itself, even hidden ones: the core's inline virtual functions (OutputPort::run,
// Encoder::run, Button::loop, ...). The loader answers each such import with a JavaScript stub
// that finds the function at its first call, so a board's vtables, which hold those imports in
// the board's part of the table, call through JavaScript on every frame (7.5 million calls a
// simulated minute of Step-A-Sketch; docs/web.md, "Figures"). Once a board is instantiated,
// each of its table slots that holds one of its function imports is set to what the stub would
// call when that is the board's own export (no global symbol of that name): the same function,
// called directly. Direct calls keep their stub. Context: the thread that loads boards.
(function bindOwnImportsOnLoad() {
  'use strict';
  if (typeof loadWebAssemblyModule !== 'function' || typeof wasmTable === 'undefined' ||
      typeof getDylinkMetadata !== 'function' || typeof resolveGlobalSymbol !== 'function') {
    return;
  }

  /// The unsigned LEB128 number at `at` in `bytes`: [value, the offset after it].
  function leb(bytes, at) {
    let value = 0;
    let shift = 0;
    let byte;
    do {
      byte = bytes[at++];
      value += (byte & 0x7f) * 2 ** shift;
      shift += 7;
    } while (byte & 0x80);
    return [value, at];
  }

  /// The names of a module's function imports, in function-index order (its import section).
  function importedFunctionNames(bytes) {
    const names = [];
    const text = (at) => {
      const [length, start] = leb(bytes, at);
      return [new TextDecoder().decode(bytes.subarray(start, start + length)), start + length];
    };
    let at = 8; // after the magic number and the version
    while (at < bytes.length) {
      const id = bytes[at];
      const [size, start] = leb(bytes, at + 1);
      if (id === 2) return readImports(bytes, start, text, names);
      at = start + size;
    }
    return names;
  }

  // The import section's entries from `at`: function imports' names into `names`.
  function readImports(bytes, at, text, names) {
    let count;
    [count, at] = leb(bytes, at);
    for (let entry = 0; entry < count; ++entry) {
      [, at] = text(at); // the module ("env", "GOT.mem", ...)
      let name;
      [name, at] = text(at);
      const kind = bytes[at++];
      if (kind === 0) {
        names.push(name);
        [, at] = leb(bytes, at); // a function: its type index
      } else if (kind === 1) {
        [, at] = limits(bytes, at + 1); // a table: element type, limits
      } else if (kind === 2) {
        [, at] = limits(bytes, at); // a memory
      } else {
        at += 2; // a global: value type, mutability
      }
    }
    return names;
  }

  function limits(bytes, at) {
    const flags = bytes[at];
    let value;
    [value, at] = leb(bytes, at + 1);
    if (flags & 1) [value, at] = leb(bytes, at);
    return [value, at];
  }

  /// Sets each slot of [base, base + size) that holds function import k of the module to its own
  /// export of that name, where the stub would have found that export; returns how many.
  function bindSlots(base, size, names, exports) {
    let bound = 0;
    for (let slot = base; slot < base + size; ++slot) {
      const entry = wasmTable.get(slot);
      // A slot holding an import is named by the import's index (V8); the module's own functions
      // come after its imports. A name that is not an index (a name section's, a JavaScript
      // function's own) binds nothing.
      const index = entry && /^\d+$/.test(entry.name) ? Number(entry.name) : NaN;
      if (!(index < names.length)) continue;
      const own = exports[names[index]];
      if (typeof own !== 'function' || resolveGlobalSymbol(names[index], false)) continue;
      wasmTable.set(slot, own);
      ++bound;
    }
    return bound;
  }

  const load = loadWebAssemblyModule;
  loadWebAssemblyModule = function (binary, flags, handle) {
    const tableLengthBefore = wasmTable.length;
    const bind = (exports) => {
      if (!(binary instanceof Uint8Array)) return exports;
      const size = getDylinkMetadata(binary).tableSize;
      const base = handle ? HEAP32[(handle + 36) >> 2] : tableLengthBefore; // where the loader put it
      Module['boundOwnImports'] = (Module['boundOwnImports'] || 0) +
        bindSlots(base, size, importedFunctionNames(binary), exports);
      return exports;
    };
    const result = load(binary, flags, handle);
    return result instanceof Promise ? result.then(bind) : bind(result);
  };
})();
