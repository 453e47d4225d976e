from app.main import entry

# as the console script: a closed pipe (python -m app register verify | head) ends quietly
raise SystemExit(entry())
