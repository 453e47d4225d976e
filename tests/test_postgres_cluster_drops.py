"""The suite's PostgreSQL cluster (tests/postgres_cluster.py) drops each test's database after
it: kept to the end, a worker's ~200 made ~1.6 GB whose removal took 10-90 s of its run."""

import psycopg


def _databases(server) -> set[str]:
    with psycopg.connect(host=str(server.socket_dir), port=server.port, user="postgres",
                         dbname="postgres", autocommit=True) as conn:
        return {row[0] for row in conn.execute("SELECT datname FROM pg_database")}


def test_a_database_made_is_dropped_with_its_session_open(postgres_server):
    url = postgres_server.new_database()
    name = url.split("@/", 1)[1].split("?", 1)[0]
    assert name in _databases(postgres_server)
    held = psycopg.connect(host=str(postgres_server.socket_dir), port=postgres_server.port,
                           user="postgres", dbname=name)  # a test may leave one open
    try:
        postgres_server.drop_database(url)
    finally:
        held.close()
    assert name not in _databases(postgres_server)
