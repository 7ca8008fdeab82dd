# Bash completion of fluidviz commands and options (issue 16). Installed by `cmake --install`
# into share/bash-completion/completions/fluidviz; or: source scripts/fluidviz-completion.bash.
# The words come from fluidviz's own help texts at completion time, so they never go stale:
# commands from `fluidviz --help`, a command's options from `fluidviz COMMAND --help`, and the
# keys after --set from `fluidviz docs --keys`. Anything else completes as a file name.
_fluidviz() {
  local cur=${COMP_WORDS[COMP_CWORD]}
  local prev=${COMP_WORDS[COMP_CWORD-1]}
  local exe=${COMP_WORDS[0]}
  if (( COMP_CWORD == 1 )); then
    local commands
    commands=$("$exe" --help 2>/dev/null | sed -n 's/^  fluidviz \([a-z][a-z0-9]*\).*/\1/p' | sort -u)
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  local command=${COMP_WORDS[1]}
  if [[ $prev == --set ]]; then
    COMPREPLY=($(compgen -S = -W "$("$exe" docs --keys 2>/dev/null)" -- "$cur"))
    compopt -o nospace 2>/dev/null
    return
  fi
  if [[ $cur == -* ]]; then
    local options
    options=$("$exe" "$command" --help 2>/dev/null | grep -oE -- '--[a-z0-9][a-z0-9-]*' | sort -u)
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
    return
  fi
  COMPREPLY=($(compgen -f -- "$cur"))
}
complete -o filenames -F _fluidviz fluidviz
