# bash completion for esc (installed as share/bash-completion/completions/esc).
# Completes subcommands, each subcommand's options, experiment names of the script on the
# line for --experiment, and files or directories where arguments are paths.
_esc() {
  local cur prev words cword
  _init_completion || return

  local commands="check run export report replay bench"
  local command="" i
  for ((i = 1; i < cword; i++)); do
    case " $commands " in *" ${words[i]} "*) command=${words[i]}; break ;; esac
  done
  if [[ -z $command ]]; then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi

  case $prev in
    --out | --cache | --resume)
      _filedir -d
      return ;;
    --script | --campaign)
      _filedir esc
      return ;;
    --format)
      COMPREPLY=($(compgen -W "csv json" -- "$cur"))
      return ;;
    --experiment)
      # The experiments declared in the script given on the line.
      local script="" w
      for w in "${words[@]}"; do [[ $w == *.esc && -f $w ]] && script=$w; done
      [[ -n $script ]] && COMPREPLY=($(compgen -W "$(sed -n 's/^[[:space:]]*experiment[[:space:]]\+\([A-Za-z_][A-Za-z0-9_]*\).*/\1/p' "$script")" -- "$cur"))
      return ;;
    --runs | --generations | --seed | --threads | --runs-at-once | --run | --epochs | --min-time | --set | --controller | --controllers | --benchmark)
      return ;;
  esac

  local options
  case $command in
    check) options="--help" ;;
    run) options="--resume --experiment --runs --generations --seed --threads --runs-at-once --out --cache --set --controllers --help" ;;
    export) options="--format --table --out --help" ;;
    report) options="--out --help" ;;
    replay) options="--controller --run --epochs --out --script --experiment --seed --animate --help" ;;
    bench) options="--threads --min-time --campaign --benchmark --help" ;;
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  elif [[ $command == export || $command == report ]]; then
    _filedir -d
  elif [[ $command == replay ]]; then
    _filedir
  else
    _filedir esc
  fi
} &&
  complete -F _esc esc
