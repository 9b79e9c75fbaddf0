# Sourced: make every python3 Debian's, even when a pyenv shim comes first on PATH.
export PYENV_VERSION=system
case ":$PATH:" in
  /usr/bin:*) ;;
  *) export PATH="/usr/bin:$PATH" ;;
esac
